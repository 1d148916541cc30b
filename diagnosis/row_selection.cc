#include "diagnosis/row_selection.h"

#include <algorithm>

#include "diagnosis/model_residuals.h"

namespace gc {

std::vector<std::size_t> time_ordered(std::span<const RecordedSample> observations) {
  std::vector<std::size_t> rows = all_rows(observations.size());
  std::stable_sort(rows.begin(), rows.end(), [&](std::size_t a, std::size_t b) {
    return observations[a].input.time_s < observations[b].input.time_s;
  });
  return rows;
}

std::vector<std::size_t> evenly_spaced(const std::vector<std::size_t>& rows, std::size_t count) {
  if (rows.size() <= count) return rows;
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < count; ++k) out.push_back(rows[k * rows.size() / count]);
  return out;
}

std::vector<std::size_t> rows_at(std::span<const std::size_t> rows, const std::vector<std::size_t>& positions) {
  std::vector<std::size_t> out;
  out.reserve(positions.size());
  for (std::size_t p : positions) out.push_back(rows[p]);
  return out;
}

Eigen::MatrixX2d select_rows(const Eigen::MatrixX2d& residual, const std::vector<std::size_t>& all,
                             const std::vector<std::size_t>& subset) {
  Eigen::MatrixX2d out(static_cast<Eigen::Index>(subset.size()), 2);
  std::size_t k = 0;
  for (std::size_t i = 0; i < all.size() && k < subset.size(); ++i) {
    if (all[i] == subset[k]) out.row(static_cast<Eigen::Index>(k++)) = residual.row(static_cast<Eigen::Index>(i));
  }
  return out;
}

}  // namespace gc
