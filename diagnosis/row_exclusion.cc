#include "diagnosis/row_exclusion.h"

#include <algorithm>

#include "diagnosis/noise_estimate.h"
#include "diagnosis/polarity_flip.h"
#include "diagnosis/row_selection.h"

namespace gc {

std::vector<std::size_t> exclude_outliers(std::vector<std::size_t>& rows, Eigen::MatrixX2d& residual, double deviations) {
  std::vector<std::size_t> outliers;
  for (std::size_t position : outlier_positions(residual, deviations)) outliers.push_back(rows[position]);
  if (outliers.empty()) return outliers;
  std::vector<std::size_t> sorted = outliers;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::size_t> kept;
  for (std::size_t r : rows) if (!std::binary_search(sorted.begin(), sorted.end(), r)) kept.push_back(r);
  residual = select_rows(residual, rows, kept);
  rows = std::move(kept);
  return outliers;
}

void exclude_moment_flips(Diagnosis& out, std::span<const RecordedSample> observations, std::vector<std::size_t>& rows,
                          Eigen::MatrixX2d& residual) {
  std::vector<std::size_t> flipped;
  for (DataQualityFinding& f : moment_polarity_flips(observations, rows, residual)) {
    flipped.insert(flipped.end(), f.rows.begin(), f.rows.end());
    out.data_quality.push_back(std::move(f));
  }
  if (flipped.empty()) return;
  std::sort(flipped.begin(), flipped.end());
  std::vector<std::size_t> kept;
  for (std::size_t r : rows) if (!std::binary_search(flipped.begin(), flipped.end(), r)) kept.push_back(r);
  residual = select_rows(residual, rows, kept);
  rows = std::move(kept);
}

}  // namespace gc
