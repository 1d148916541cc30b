// Results between core value types and the IDL's C types, member for member, so a result that
// crossed the wire compares equal, bit for bit, with the in-process one.
#pragma once

#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/jam_angle.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"
#include "gearcoupling.h"
#include "protocol/batch_types.h"
#include "protocol/jam_angle_result.h"

namespace gc::protocol {

void to_wire(const ToothContact& in, gearcoupling_ToothContactResult& out);
ToothContact from_wire(const gearcoupling_ToothContactResult& in);

void to_wire(const protocol::JamAngleResult& in, gearcoupling_JamAngleResult& out);
protocol::JamAngleResult from_wire(const gearcoupling_JamAngleResult& in);

void to_wire(const InducedMoments& in, gearcoupling_InducedMomentsResult& out);
InducedMoments from_wire(const gearcoupling_InducedMomentsResult& in);

void to_wire(const RestoringTorque& in, gearcoupling_RestoringTorqueResult& out);
RestoringTorque from_wire(const gearcoupling_RestoringTorqueResult& in);

void to_wire(const FrictionEstimate& in, gearcoupling_FrictionEstimateResult& out);
FrictionEstimate from_wire(const gearcoupling_FrictionEstimateResult& in);

/// A batch's answers (wire_batch.cc). to_wire cuts each case's field and message to
/// kMaxBatchCaseTextBytes.
void to_wire(const BatchResult& in, gearcoupling_BatchResult& out);
BatchResult from_wire(const gearcoupling_BatchResult& in);

}  // namespace gc::protocol
