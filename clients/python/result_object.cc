#include "clients/python/result_object.h"

#include "codec/result_json.h"
#include "codec/result_messages.h"

namespace py = pybind11;

namespace gc::python {

py::object result_object(const char* type_name, const google::protobuf::Message& message) {
  return py::module_::import("gearcoupling._results").attr(type_name)(codec::to_json(message));
}

py::object tooth_contact_result(const std::string& coupling, const OperatingPoint& point,
                                const ToothContact& contact) {
  return result_object("ToothContactResult", codec::to_message(coupling, point, contact));
}

py::object induced_moments_result(const std::string& coupling, const OperatingPoint& point,
                                  const ToothContact& contact, const InducedMoments& moments) {
  return result_object("InducedMomentsResult", codec::to_message(coupling, point, contact, moments));
}

py::object jam_angle_result(const std::string& coupling, const JamAngle& jam, double crown_radius_m,
                            bool crown_radius_derived) {
  return result_object("JamAngleResult",
                       codec::to_message(coupling, jam, crown_radius_m, crown_radius_derived));
}

py::object restoring_torque_result(const std::string& coupling, const RestoringTorque& torque) {
  return result_object("RestoringTorqueResult", codec::to_message(coupling, torque));
}

py::object friction_estimate_result(const std::string& coupling, const FrictionMeasurement& measurement,
                                    const FrictionEstimate& estimate) {
  return result_object("FrictionEstimateResult", codec::to_message(coupling, measurement, estimate));
}

ContactOptions contact_options(int slices, double tolerance, int max_iterations) {
  ContactOptions options;
  options.slices = slices;
  options.load_sharing.tolerance = tolerance;
  options.load_sharing.max_iterations = max_iterations;
  return options;
}

}  // namespace gc::python
