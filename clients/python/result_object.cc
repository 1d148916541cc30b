#include "clients/python/result_object.h"

#include "codec/result_json.h"
#include "codec/result_messages.h"

namespace py = pybind11;

namespace gc::python {

namespace {

py::dict point_radians(double misalignment_rad, double direction_rad) {
  py::dict out;
  out["misalignment_rad"] = misalignment_rad;
  out["direction_rad"] = direction_rad;
  return out;
}

}  // namespace

py::object result_object(const char* type_name, const google::protobuf::Message& message,
                         py::dict radians) {
  return py::module_::import("gearcoupling._results").attr(type_name)(codec::to_json(message), radians);
}

ToothContactResultObject tooth_contact_result(const std::string& coupling, const OperatingPoint& point,
                                              const ToothContact& contact) {
  py::dict radians;
  radians["operating_point"] = point_radians(point.misalignment_rad, point.direction_rad);
  radians["offset_alpha_rad"] = contact.offset_alpha_rad;
  radians["z_axis_angle_rad"] = contact.z_axis_angle_rad;
  py::list teeth;
  for (const ToothLoad& tooth : contact.teeth) {
    py::dict one;
    one["angle_rad"] = tooth.angle_rad;
    teeth.append(one);
  }
  radians["teeth"] = teeth;
  return result_object("ToothContactResult", codec::to_message(coupling, point, contact), radians);
}

InducedMomentsResultObject induced_moments_result(const std::string& coupling,
                                                  const OperatingPoint& point,
                                                  const ToothContact& contact,
                                                  const InducedMoments& moments) {
  py::dict radians;
  radians["operating_point"] = point_radians(point.misalignment_rad, point.direction_rad);
  radians["direction_rad"] = moments.direction_rad;
  return result_object("InducedMomentsResult", codec::to_message(coupling, point, contact, moments),
                       radians);
}

JamAngleResultObject jam_angle_result(const std::string& coupling, const JamAngle& jam,
                                      double crown_radius_m, bool crown_radius_derived) {
  py::dict radians;
  radians["angle_rad"] = jam.angle_rad;
  if (jam.both_flanks_rad) radians["both_flanks_rad"] = *jam.both_flanks_rad;
  radians["facewidth_rad"] = jam.facewidth_rad;
  radians["radial_rad"] = jam.radial_rad;
  return result_object("JamAngleResult",
                       codec::to_message(coupling, jam, crown_radius_m, crown_radius_derived),
                       radians);
}

RestoringTorqueResultObject restoring_torque_result(const std::string& coupling,
                                                    const RestoringTorque& torque) {
  return result_object("RestoringTorqueResult", codec::to_message(coupling, torque));
}

FrictionEstimateResultObject friction_estimate_result(const std::string& coupling,
                                                      const FrictionMeasurement& measurement,
                                                      const FrictionEstimate& estimate) {
  py::dict radians;
  radians["measurement"] = point_radians(measurement.misalignment_rad, measurement.direction_rad);
  return result_object("FrictionEstimateResult", codec::to_message(coupling, measurement, estimate),
                       radians);
}

ContactOptions contact_options(int slices, double tolerance, int max_iterations) {
  ContactOptions options;
  options.slices = slices;
  options.load_sharing.tolerance = tolerance;
  options.load_sharing.max_iterations = max_iterations;
  return options;
}

}  // namespace gc::python
