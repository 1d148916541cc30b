// What each calculation takes and returns, in core types only: the public client's API
// (client/client.h) names them without the wire types of calculation_traits.h.
#pragma once

#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"
#include "protocol/batch_types.h"
#include "protocol/calculation.h"
#include "protocol/jam_angle_result.h"
#include "protocol/requests.h"

namespace gc::protocol {

template <Calculation kCalculation>
struct CalculationTypes;

template <>
struct CalculationTypes<Calculation::kToothContact> {
  using Request = ToothContactRequest;
  using Result = gc::ToothContact;
};
template <>
struct CalculationTypes<Calculation::kJamAngle> {
  using Request = JamAngleRequest;
  using Result = JamAngleResult;
};
template <>
struct CalculationTypes<Calculation::kInducedMoments> {
  using Request = InducedMomentsRequest;
  using Result = gc::InducedMoments;
};
template <>
struct CalculationTypes<Calculation::kRestoringTorque> {
  using Request = RestoringTorqueRequest;
  using Result = gc::RestoringTorque;
};
template <>
struct CalculationTypes<Calculation::kFrictionEstimate> {
  using Request = FrictionEstimateRequest;
  using Result = gc::FrictionEstimate;
};
template <>
struct CalculationTypes<Calculation::kBatch> {
  using Request = BatchRequest;
  using Result = BatchResult;
};

}  // namespace gc::protocol
