// A torque of the wrong sign: the model takes the torque as a magnitude (T > 0) and refuses a
// negative one. A dyno that logs the drive torque negative has every row negative (--negate torque
// reads it); a channel whose polarity flips partway has some rows of each sign. Either way the rows
// are refused by the model, counted and named here with the advice, never passed off as noise.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/diagnosis/data_quality.h"

namespace gc {

/// The rows with a negative torque, with the advice: --negate torque when all are negative; when
/// the sign turns partway, where it turns and that the parts need reading apart.
std::optional<DataQualityFinding> negative_torque(std::span<const RecordedSample> observations,
                                                  const std::vector<std::size_t>& ordered);

}  // namespace gc
