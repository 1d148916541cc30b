// Results as Python objects: the message the CLI prints with --json (codec/result_messages.h,
// idl/*.proto), handed to its class in gearcoupling/_results.py, whose .to_dict() is that JSON
// parsed and whose attributes are its fields (units in their names).
#pragma once

#include <string>

#include <google/protobuf/message.h>
#include <pybind11/pybind11.h>

#include "clients/python/typed_objects.h"

#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/jam_angle.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"

namespace gc::python {

/// gearcoupling._results.<type_name>(codec::to_json(message), radians). Needs the GIL.
/// `radians`: the exact radians of the message's `_deg` fields, as a dict shaped like the
/// message (`{"direction_rad": ..., "operating_point": {"misalignment_rad": ...}, "teeth":
/// [{"angle_rad": ...}, ...]}`): each `X_deg` field then has an attribute `X_rad` with the value
/// the core computed or was given, not one converted back from degrees.
pybind11::object result_object(const char* type_name, const google::protobuf::Message& message,
                               pybind11::dict radians = {});

// One calculation's result object, from the core's result (in process or from the service).
ToothContactResultObject tooth_contact_result(const std::string& coupling, const OperatingPoint& point,
                                              const ToothContact& contact);
InducedMomentsResultObject induced_moments_result(const std::string& coupling,
                                                  const OperatingPoint& point,
                                                  const ToothContact& contact,
                                                  const InducedMoments& moments);
JamAngleResultObject jam_angle_result(const std::string& coupling, const JamAngle& jam,
                                      double crown_radius_m, bool crown_radius_derived);
RestoringTorqueResultObject restoring_torque_result(const std::string& coupling,
                                                    const RestoringTorque& torque);
FrictionEstimateResultObject friction_estimate_result(const std::string& coupling,
                                                      const FrictionMeasurement& measurement,
                                                      const FrictionEstimate& estimate);

/// The contact options of every calculation that solves the tooth contact, from the keyword
/// arguments (defaults: ContactOptions{}); the core checks their ranges and names the field.
ContactOptions contact_options(int slices, double tolerance, int max_iterations);

/// Adds the contact options' keyword arguments to a binding.
#define GC_PYTHON_CONTACT_OPTION_ARGS                                                       \
  pybind11::arg("slices") = ::gc::ContactOptions{}.slices,                                  \
  pybind11::arg("tolerance") = ::gc::ContactOptions{}.load_sharing.tolerance,               \
  pybind11::arg("max_iterations") = ::gc::ContactOptions{}.load_sharing.max_iterations

}  // namespace gc::python
