// Residuals of a model against measured moments: measured minus predicted, per channel.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"

namespace gc {

struct ModelResiduals {
  /// Row k holds M_sy' and M_sz' measured minus predicted for rows[k] [N·m]; rows the model
  /// cannot predict hold zeros and are listed in failed_rows.
  Eigen::MatrixX2d residual;
  std::vector<std::size_t> failed_rows;  ///< indices into `observations`
  std::string first_failure;             ///< the model's message for the first failed row
};

/// Predicts every listed row (any order, possibly concurrently through `parallel`). A row whose
/// prediction throws ModelError (e.g. the effective misalignment at the jam angle) is reported,
/// never dropped silently.
ModelResiduals model_residuals(const CouplingModel& model, std::span<const RecordedSample> observations,
                               std::span<const std::size_t> rows, const ParallelFor& parallel);

/// 0, 1, ..., count - 1: every row of a recording.
std::vector<std::size_t> all_rows(std::size_t count);

}  // namespace gc
