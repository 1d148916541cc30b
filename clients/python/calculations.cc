// The five calculations in process, one case at a time, with the GIL released while the core
// runs. Arguments in SI (N·m, rad); results as gearcoupling/_results.py's classes.
#include "clients/python/bindings.h"
#include "clients/python/coupling_argument.h"
#include "clients/python/result_object.h"
#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"

namespace py = pybind11;

namespace gc::python {
namespace {

// What tooth_contact and induced_moments both take: the coupling, the point, the options.
struct LoadCaseArguments {
  std::shared_ptr<const Coupling> coupling;
  OperatingPoint point;
  ContactOptions options;
};

LoadCaseArguments load_case_arguments(const CouplingArgument& coupling, double torque_nm, double misalignment_rad,
                                      double direction_rad, double mu, int slices, double tolerance,
                                      int max_iterations) {
  return {coupling_argument(coupling), {torque_nm, misalignment_rad, direction_rad, mu},
          contact_options(slices, tolerance, max_iterations)};
}

ToothContactResultObject tooth_contact(const CouplingArgument& coupling, double torque_nm, double misalignment_rad,
                         double direction_rad, double mu, int slices, double tolerance,
                         int max_iterations) {
  const LoadCaseArguments a = load_case_arguments(coupling, torque_nm, misalignment_rad, direction_rad,
                                                  mu, slices, tolerance, max_iterations);
  ToothContact contact;
  {
    py::gil_scoped_release release;
    contact = gc::tooth_contact(*a.coupling->geometry, a.point, a.options);
  }
  return tooth_contact_result(a.coupling->geometry->name(), a.point, contact);
}

InducedMomentsResultObject induced_moments(const CouplingArgument& coupling, double torque_nm, double misalignment_rad,
                           double direction_rad, double mu, int slices, double tolerance,
                           int max_iterations) {
  const LoadCaseArguments a = load_case_arguments(coupling, torque_nm, misalignment_rad, direction_rad,
                                                  mu, slices, tolerance, max_iterations);
  const CouplingGeometry& geometry = *a.coupling->geometry;
  ToothContact contact;
  InducedMoments moments;
  {
    py::gil_scoped_release release;
    contact = gc::tooth_contact(geometry, a.point, a.options);
    moments = gc::induced_moments(geometry, a.point, contact);
  }
  return induced_moments_result(geometry.name(), a.point, contact, moments);
}

JamAngleResultObject jam_angle(const CouplingArgument& coupling) {
  const auto c = coupling_argument(coupling);
  const CouplingGeometry& g = *c->geometry;
  return jam_angle_result(g.name(), g.jam_angle(), g.crown_radius_m(), g.crown_radius_derived());
}

RestoringTorqueResultObject restoring_torque(const CouplingArgument& coupling) {
  const auto c = coupling_argument(coupling);
  return restoring_torque_result(c->geometry->name(), gc::restoring_torque(*c->geometry));
}

FrictionEstimateResultObject estimate_friction(const CouplingArgument& coupling, double torque_nm, double misalignment_rad,
                             double direction_rad, double sensor_moment_y_nm,
                             double sensor_moment_z_nm) {
  const auto c = coupling_argument(coupling);
  const FrictionMeasurement measurement{torque_nm, misalignment_rad, direction_rad,
                                        sensor_moment_y_nm, sensor_moment_z_nm};
  return friction_estimate_result(c->geometry->name(), measurement,
                                  gc::estimate_friction(*c->geometry, measurement));
}

}  // namespace

void bind_calculations(py::module_& m) {
  m.def("tooth_contact", &tooth_contact, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(),
        py::arg("mu") = 0.0, GC_PYTHON_CONTACT_OPTION_ARGS,
        "Tooth contact at one load case (eqs 5-22): load sharing q, every tooth's load P_d [N], "
        "contact offset and zone [m], the most loaded tooth's stress [Pa]. coupling: a Coupling, "
        "catalogue name, coupling file or dict; torque_nm: T [N·m] > 0; misalignment_rad: zeta "
        "[rad], below the jam angle; direction_rad: beta [rad]; mu: not used (recorded); slices: "
        "N_s (even, eq 14); tolerance, max_iterations: eqs 20-22. Returns ToothContactResult "
        "(gearcoupling contact --json).");
  m.def("induced_moments", &induced_moments, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(), py::arg("mu"),
        GC_PYTHON_CONTACT_OPTION_ARGS,
        "Induced bending moments at one load case (eqs 36-48) in the double-prime frame, the "
        "coupling frame and at the sensors [N·m]. mu: tooth sliding friction [-], 0..1. Other "
        "arguments as tooth_contact. Returns InducedMomentsResult (gearcoupling moments --json).");
  m.def("jam_angle", &jam_angle, py::arg("coupling"),
        "The jam angle and its three criteria (eqs 23-35) [rad, deg]. Returns JamAngleResult "
        "(gearcoupling jam-angle --json).");
  m.def("restoring_torque", &restoring_torque, py::arg("coupling"),
        "The torque that lifts the hub off the sleeve (eqs 49-53) [N·m]. Returns "
        "RestoringTorqueResult (gearcoupling restoring-torque --json).");
  m.def("estimate_friction", &estimate_friction, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad"), py::arg("sensor_moment_y_nm"),
        py::arg("sensor_moment_z_nm"),
        "The friction coefficient mu [-] from measured torque [N·m], misalignment and direction "
        "[rad] and sensor moments M_sy', M_sz' [N·m] (eqs 1-4). Returns FrictionEstimateResult "
        "(gearcoupling friction --json).");
}

}  // namespace gc::python
