// Core results -> the messages of idl/results.proto. Radians become the _deg fields here; every
// other quantity is copied in SI.
#pragma once

#include <string_view>

#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/jam_angle.h"
#include "core/operating_point.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"
#include "idl/results.pb.h"

namespace gc::codec {

namespace v1 = ::gearcoupling::v1;

v1::OperatingPointRecord to_message(const OperatingPoint& point);

/// Every tooth with its slice loads and positions (eq 14).
v1::ToothContactResult to_message(std::string_view coupling, const OperatingPoint& point,
                                  const ToothContact& contact);

/// `crown_radius_m` and `crown_radius_derived` describe the R_F the jam angle used.
v1::JamAngleResult to_message(std::string_view coupling, const JamAngle& jam,
                              double crown_radius_m, bool crown_radius_derived);

v1::InducedMomentsResult to_message(std::string_view coupling, const OperatingPoint& point,
                                    const ToothContact& contact, const InducedMoments& moments);

v1::RestoringTorqueResult to_message(std::string_view coupling, const RestoringTorque& torque);

v1::FrictionEstimateResult to_message(std::string_view coupling,
                                      const FrictionMeasurement& measurement,
                                      const FrictionEstimate& estimate);

}  // namespace gc::codec
