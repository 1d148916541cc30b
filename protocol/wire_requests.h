// Whole requests between core value types (requests.h) and the IDL's C types. Correlation is
// written by the caller.
#pragma once

#include "gearcoupling.h"
#include "protocol/batch_types.h"
#include "protocol/requests.h"

namespace gc::protocol {

void to_wire(const ToothContactRequest& in, gearcoupling_ToothContactRequest& out);
void to_wire(const JamAngleRequest& in, gearcoupling_JamAngleRequest& out);
void to_wire(const InducedMomentsRequest& in, gearcoupling_InducedMomentsRequest& out);
void to_wire(const RestoringTorqueRequest& in, gearcoupling_RestoringTorqueRequest& out);
void to_wire(const FrictionEstimateRequest& in, gearcoupling_FrictionEstimateRequest& out);

ToothContactRequest from_wire(const gearcoupling_ToothContactRequest& in);
JamAngleRequest from_wire(const gearcoupling_JamAngleRequest& in);
InducedMomentsRequest from_wire(const gearcoupling_InducedMomentsRequest& in);
RestoringTorqueRequest from_wire(const gearcoupling_RestoringTorqueRequest& in);
FrictionEstimateRequest from_wire(const gearcoupling_FrictionEstimateRequest& in);

/// A batch (wire_batch.cc). from_wire refuses the whole batch, before converting any case, with
/// InvalidInput("cases") above kMaxBatchCases, InvalidInput("couplings") with none or above
/// kMaxBatchCouplings, InvalidInput("calculation") for a value outside BatchCalculation, and
/// InvalidInput("couplings[i]") for a coupling reference the single requests' from_wire refuses
/// (a name over kMaxNameBytes, an unknown CouplingSource). A case naming a coupling index out
/// of range is answered in place by the service, not refused here.
void to_wire(const BatchRequest& in, gearcoupling_BatchRequest& out);
BatchRequest from_wire(const gearcoupling_BatchRequest& in);

}  // namespace gc::protocol
