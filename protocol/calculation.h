// The calculations the service offers, one request/reply topic pair each.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace gc::protocol {

enum class Calculation {
  kToothContact,
  kJamAngle,
  kInducedMoments,
  kRestoringTorque,
  kFrictionEstimate,
  kBatch,  ///< many cases of one of the others in one request (protocol/batch_types.h, issue 40)
};

/// How many calculations (request/reply topic pairs) there are.
inline constexpr std::size_t kCalculationCount = 6;

inline constexpr std::array<Calculation, kCalculationCount> kAllCalculations = {
    Calculation::kToothContact,    Calculation::kJamAngle,         Calculation::kInducedMoments,
    Calculation::kRestoringTorque, Calculation::kFrictionEstimate, Calculation::kBatch};

/// "tooth_contact", "jam_angle", "induced_moments", "restoring_torque", "friction_estimate",
/// "batch":
/// the middle part of the topic names and the name in the status topic and the logs.
std::string_view to_string(Calculation calculation);

/// Index 0..5 of `calculation` in kAllCalculations.
constexpr std::size_t index_of(Calculation calculation) {
  return static_cast<std::size_t>(calculation);
}

}  // namespace gc::protocol
