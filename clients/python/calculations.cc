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

py::object tooth_contact(py::handle coupling, double torque_nm, double misalignment_rad,
                         double direction_rad, double mu, int slices, double tolerance,
                         int max_iterations) {
  const auto c = coupling_argument(coupling);
  const OperatingPoint point{torque_nm, misalignment_rad, direction_rad, mu};
  const ContactOptions options = contact_options(slices, tolerance, max_iterations);
  ToothContact contact;
  {
    py::gil_scoped_release release;
    contact = gc::tooth_contact(*c->geometry, point, options);
  }
  return tooth_contact_result(c->geometry->name(), point, contact);
}

py::object induced_moments(py::handle coupling, double torque_nm, double misalignment_rad,
                           double direction_rad, double mu, int slices, double tolerance,
                           int max_iterations) {
  const auto c = coupling_argument(coupling);
  const OperatingPoint point{torque_nm, misalignment_rad, direction_rad, mu};
  const ContactOptions options = contact_options(slices, tolerance, max_iterations);
  ToothContact contact;
  InducedMoments moments;
  {
    py::gil_scoped_release release;
    contact = gc::tooth_contact(*c->geometry, point, options);
    moments = gc::induced_moments(*c->geometry, point, contact);
  }
  return induced_moments_result(c->geometry->name(), point, contact, moments);
}

py::object jam_angle(py::handle coupling) {
  const auto c = coupling_argument(coupling);
  const CouplingGeometry& g = *c->geometry;
  return jam_angle_result(g.name(), g.jam_angle(), g.crown_radius_m(), g.crown_radius_derived());
}

py::object restoring_torque(py::handle coupling) {
  const auto c = coupling_argument(coupling);
  return restoring_torque_result(c->geometry->name(), gc::restoring_torque(*c->geometry));
}

py::object estimate_friction(py::handle coupling, double torque_nm, double misalignment_rad,
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
        py::arg("mu") = 0.0, GC_PYTHON_CONTACT_OPTION_ARGS);
  m.def("induced_moments", &induced_moments, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad") = 0.0, py::kw_only(), py::arg("mu"),
        GC_PYTHON_CONTACT_OPTION_ARGS);
  m.def("jam_angle", &jam_angle, py::arg("coupling"));
  m.def("restoring_torque", &restoring_torque, py::arg("coupling"));
  m.def("estimate_friction", &estimate_friction, py::arg("coupling"), py::arg("torque_nm"),
        py::arg("misalignment_rad"), py::arg("direction_rad"), py::arg("sensor_moment_y_nm"),
        py::arg("sensor_moment_z_nm"));
}

}  // namespace gc::python
