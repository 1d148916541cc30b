// The core call behind each request: the same functions the in-process CLI calls, so a remote
// result equals the in-process one bit for bit.
#pragma once

#include "core/coupling_geometry.h"
#include "protocol/jam_angle_result.h"
#include "protocol/requests.h"
#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/jam_angle.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"

namespace gc::service {

ToothContact compute(const CouplingGeometry& coupling, const protocol::ToothContactRequest& request);
/// The jam angle is part of the validated geometry (eqs 23-35 run once per coupling).
protocol::JamAngleResult compute(const CouplingGeometry& coupling, const protocol::JamAngleRequest& request);
InducedMoments compute(const CouplingGeometry& coupling,
                       const protocol::InducedMomentsRequest& request);
RestoringTorque compute(const CouplingGeometry& coupling,
                        const protocol::RestoringTorqueRequest& request);
FrictionEstimate compute(const CouplingGeometry& coupling,
                         const protocol::FrictionEstimateRequest& request);

}  // namespace gc::service
