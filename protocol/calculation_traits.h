// One table binding each calculation to its request and result types, its IDL C types and
// their type descriptors, so the service and the client library handle all five with one
// generic piece of code each.
#pragma once

#include <dds/dds.h>

#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/jam_angle.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"
#include "gearcoupling.h"
#include "protocol/calculation.h"
#include "protocol/calculation_types.h"
#include "protocol/jam_angle_result.h"
#include "protocol/requests.h"

namespace gc::protocol {

template <Calculation kCalculation>
struct CalculationTraits;

#define GC_PROTOCOL_CALCULATION_TRAITS(ENUM, NAME)                                       \
  template <>                                                                            \
  struct CalculationTraits<Calculation::ENUM> : CalculationTypes<Calculation::ENUM> {     \
    static constexpr Calculation kId = Calculation::ENUM;                                \
    using WireRequest = gearcoupling_##NAME##Request;                                    \
    using WireReply = gearcoupling_##NAME##Reply;                                        \
    static const dds_topic_descriptor_t& request_type() {                                \
      return gearcoupling_##NAME##Request_desc;                                          \
    }                                                                                    \
    static const dds_topic_descriptor_t& reply_type() { return gearcoupling_##NAME##Reply_desc; } \
  };

GC_PROTOCOL_CALCULATION_TRAITS(kToothContact, ToothContact)
GC_PROTOCOL_CALCULATION_TRAITS(kJamAngle, JamAngle)
GC_PROTOCOL_CALCULATION_TRAITS(kInducedMoments, InducedMoments)
GC_PROTOCOL_CALCULATION_TRAITS(kRestoringTorque, RestoringTorque)
GC_PROTOCOL_CALCULATION_TRAITS(kFrictionEstimate, FrictionEstimate)
GC_PROTOCOL_CALCULATION_TRAITS(kBatch, Batch)

#undef GC_PROTOCOL_CALCULATION_TRAITS

/// Calls f(std::integral_constant<Calculation, c>{}) for each of the six calculations.
template <typename Function>
void for_each_calculation(Function&& f) {
  f(std::integral_constant<Calculation, Calculation::kToothContact>{});
  f(std::integral_constant<Calculation, Calculation::kJamAngle>{});
  f(std::integral_constant<Calculation, Calculation::kInducedMoments>{});
  f(std::integral_constant<Calculation, Calculation::kRestoringTorque>{});
  f(std::integral_constant<Calculation, Calculation::kFrictionEstimate>{});
  f(std::integral_constant<Calculation, Calculation::kBatch>{});
}

}  // namespace gc::protocol
