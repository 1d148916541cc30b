#include "diagnosis/row_exclusion.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "diagnosis/model_jumps.h"
#include "diagnosis/noise_estimate.h"
#include "diagnosis/polarity_flip.h"
#include "diagnosis/quantisation.h"
#include "diagnosis/row_selection.h"

namespace gc {
namespace {

/// `rows` and `residual` without `excluded` (ascending).
void leave_out(const std::vector<std::size_t>& excluded, std::vector<std::size_t>& rows, Eigen::MatrixX2d& residual) {
  if (excluded.empty()) return;
  std::vector<std::size_t> kept;
  for (std::size_t r : rows) if (!std::binary_search(excluded.begin(), excluded.end(), r)) kept.push_back(r);
  residual = select_rows(residual, rows, kept);
  rows = std::move(kept);
}

}  // namespace

std::vector<std::size_t> exclude_outliers(std::span<const RecordedSample> observations, std::vector<std::size_t>& rows,
                                          Eigen::MatrixX2d& residual, double deviations) {
  // Rounding to a step q adds q / sqrt(12) of white noise (quantisation.h).
  Eigen::Array2d rounding = Eigen::Array2d::Zero();
  for (int c = 0; c < 2; ++c) {
    std::vector<double> values;
    values.reserve(rows.size());
    for (std::size_t r : rows) values.push_back(c == 0 ? observations[r].measured.y_nm : observations[r].measured.z_nm);
    if (const std::optional<double> step = quantisation_step(values)) rounding(c) = *step / std::sqrt(12.0);
  }
  std::vector<std::size_t> outliers;
  for (std::size_t position : outlier_positions(residual, deviations, rounding)) outliers.push_back(rows[position]);
  std::vector<std::size_t> sorted = outliers;
  std::sort(sorted.begin(), sorted.end());
  leave_out(sorted, rows, residual);
  return outliers;
}

void exclude_moment_flips(Diagnosis& out, std::span<const RecordedSample> observations, std::vector<std::size_t>& rows,
                          Eigen::MatrixX2d& residual) {
  std::vector<std::size_t> flipped;
  for (DataQualityFinding& f : moment_polarity_flips(observations, rows, residual)) {
    flipped.insert(flipped.end(), f.rows.begin(), f.rows.end());
    out.data_quality.push_back(std::move(f));
  }
  std::sort(flipped.begin(), flipped.end());
  leave_out(flipped, rows, residual);
}

void exclude_rows_at_model_jumps(Diagnosis& out, const CouplingModel& model, std::span<const RecordedSample> observations,
                                 std::vector<std::size_t>& rows, Eigen::MatrixX2d& residual, const ParallelFor& parallel) {
  std::optional<DataQualityFinding> jumps =
      rows_at_model_jumps(model, observations, rows, estimate_noise(residual).pooled_sigma_nm(), parallel);
  if (!jumps) return;
  leave_out(jumps->rows, rows, residual);
  out.data_quality.push_back(std::move(*jumps));
}

}  // namespace gc
