#include "diagnosis/model_residuals.h"

#include <algorithm>
#include <mutex>
#include <numeric>


namespace gc {

ModelResiduals model_residuals(const CouplingModel& model, std::span<const RecordedSample> observations,
                               std::span<const std::size_t> rows, const ParallelFor& parallel) {
  ModelResiduals out;
  out.residual = Eigen::MatrixX2d::Zero(static_cast<Eigen::Index>(rows.size()), 2);
  std::mutex mutex;
  std::vector<std::pair<std::size_t, std::string>> failures;
  parallel(rows.size(), [&](std::size_t begin, std::size_t end) {
    // The rows of a chunk at once: a model that reads the history shares its passes between them
    // (CouplingModel::moments_at), with the numbers of predict_at row by row, whatever the chunks.
    const CouplingModel::MomentsAtRows m = model.moments_at(observations, rows.subspan(begin, end - begin));
    for (std::size_t k = begin; k < end; ++k) {
      if (!m.errors[k - begin].empty()) {
        const std::lock_guard<std::mutex> lock(mutex);
        failures.emplace_back(rows[k], m.errors[k - begin]);
        continue;
      }
      const RecordedSample& o = observations[rows[k]];
      out.residual(static_cast<Eigen::Index>(k), 0) = o.measured.y_nm - m.moments[k - begin].y_nm;
      out.residual(static_cast<Eigen::Index>(k), 1) = o.measured.z_nm - m.moments[k - begin].z_nm;
    }
  });
  // Sorted, so the report does not depend on which thread met a failure first.
  std::sort(failures.begin(), failures.end());
  for (const auto& failure : failures) out.failed_rows.push_back(failure.first);
  if (!failures.empty()) out.first_failure = failures.front().second;
  return out;
}

std::vector<std::size_t> all_rows(std::size_t count) {
  std::vector<std::size_t> rows(count);
  std::iota(rows.begin(), rows.end(), std::size_t{0});
  return rows;
}

}  // namespace gc
