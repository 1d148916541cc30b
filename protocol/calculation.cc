#include "protocol/calculation.h"

namespace gc::protocol {

std::string_view to_string(Calculation calculation) {
  switch (calculation) {
    case Calculation::kToothContact: return "tooth_contact";
    case Calculation::kJamAngle: return "jam_angle";
    case Calculation::kInducedMoments: return "induced_moments";
    case Calculation::kRestoringTorque: return "restoring_torque";
    case Calculation::kFrictionEstimate: return "friction_estimate";
    case Calculation::kBatch: return "batch";
  }
  return "unknown";
}

}  // namespace gc::protocol
