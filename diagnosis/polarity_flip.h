// A torque of the wrong sign: the model takes the torque as a magnitude (T > 0) and refuses a
// negative one. A dyno that logs the drive torque negative has every row negative (--negate torque
// reads it); a channel whose polarity flips partway has some rows of each sign. Either way the rows
// are refused by the model, counted and named here with the advice, never passed off as noise.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "diagnosis/data_quality.h"

namespace gc {

/// The rows with a negative torque, with the advice: --negate torque when all are negative; when
/// the sign turns partway, where it turns and that the parts need reading apart.
std::optional<DataQualityFinding> negative_torque(std::span<const RecordedSample> observations,
                                                  const std::vector<std::size_t>& ordered);

/// A moment channel whose sign turns from a row to the end (a swapped bridge lead), or is opposite
/// on every row: from the split k that best fits the measurement by the model's moment before it
/// and by its negative after, when the negative leaves under a quarter of what the model leaves on
/// those rows and the model's moment there is more than twice what the negative leaves (a channel
/// the model predicts near zero cannot show it). `rows` (time order) and `residual` (measured -
/// predicted on them) as model_residuals gives them. The rows are excluded: they measured the
/// coupling with the wrong sign.
std::vector<DataQualityFinding> moment_polarity_flips(std::span<const RecordedSample> observations,
                                                      const std::vector<std::size_t>& rows,
                                                      const Eigen::MatrixX2d& residual);

}  // namespace gc
