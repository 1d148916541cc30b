#include "core/diagnosis/polarity_flip.h"

#include <algorithm>
#include <string>

#include "core/engineering_text.h"

namespace gc {

std::optional<DataQualityFinding> negative_torque(std::span<const RecordedSample> observations,
                                                  const std::vector<std::size_t>& ordered) {
  DataQualityFinding finding{DataQualityKind::polarity_flip, "torque", {}, {}, true, ""};
  std::optional<double> first_negative;
  for (std::size_t r : ordered) {
    if (!(observations[r].input.torque_nm < 0.0)) continue;
    finding.rows.push_back(r);
    if (!first_negative) first_negative = observations[r].input.time_s;
  }
  if (finding.rows.empty()) return std::nullopt;
  std::sort(finding.rows.begin(), finding.rows.end());
  const std::string count = std::to_string(finding.rows.size()) + " of " + std::to_string(observations.size()) + " rows";
  if (finding.rows.size() == observations.size()) {
    finding.detail = "the torque is negative on all " + std::to_string(finding.rows.size()) +
                     " rows, as a dyno that logs the drive torque negative writes it; --negate torque reads it (the "
                     "model takes the torque as a magnitude, T > 0); refused by the model";
    return finding;
  }
  finding.detail = "the torque is negative on " + std::to_string(finding.rows.size()) + " of " +
                   std::to_string(observations.size()) + " rows, from t = " + engineering_text(*first_negative, "s") +
                   ": its sign turns partway (a channel's polarity swapped). The model takes the torque as a "
                   "magnitude (T > 0); --negate torque reads a torque logged negative, so split the recording where "
                   "the sign turns and read the negative part with --negate torque; refused by the model";
  return finding;
}

}  // namespace gc
