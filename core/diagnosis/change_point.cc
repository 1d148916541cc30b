#include "core/diagnosis/change_point.h"

#include <algorithm>
#include <cmath>

namespace gc {
namespace {

constexpr Eigen::Index kFewestRows = 40;
/// The standardised CUSUM maximum that a single change must exceed, in units of the noise's
/// correlation (sqrt of its variance inflation): the supremum of a Brownian bridge over the middle
/// 90 % exceeds 4 about once in ten thousand. Without it, the strongest wander of pure noise is
/// offered, and since its time was picked on every row, the cross-validation cannot reject it.
constexpr double kLeastStatistic = 4.0;
constexpr Eigen::Index kEdgeShare = 20;  ///< a change leaves at least 1/20 of the rows either side

}  // namespace

std::optional<double> dominant_step_time(std::span<const RecordedSample> observations,
                                         std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual) {
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  if (n < kFewestRows) return std::nullopt;
  // Centred only: the inputs of a test programme change by phases (a staircase, then sweeps, then
  // a speed run), so a regression on them takes a step's share wherever a phase boundary is near
  // it (a bridge re-zeroed at 687 s was found at 1134 s). What the step competes with is the
  // formula's business: this only offers the time.
  const Eigen::MatrixX2d e = residual.rowwise() - residual.colwise().mean();
  double best = 0.0;
  Eigen::Index at = -1;
  for (int c = 0; c < 2; ++c) {
    const double scale = e.col(c).norm() / std::sqrt(static_cast<double>(n));
    if (!(scale > 0.0)) continue;
    // The residual's own lag-1 correlation: a step inflates it too, but far less than it lifts C.
    const double phi = std::clamp(e.col(c).head(n - 1).dot(e.col(c).tail(n - 1)) / e.col(c).squaredNorm(), 0.0, 0.99);
    const double least = kLeastStatistic * std::sqrt((1.0 + phi) / (1.0 - phi));
    const double total = e.col(c).sum();
    double partial = 0.0;
    for (Eigen::Index k = 1; k < n; ++k) {
      partial += e(k - 1, c);
      if (k < n / kEdgeShare || n - k < n / kEdgeShare) continue;
      const double kk = static_cast<double>(k), nn = static_cast<double>(n);
      const double statistic = std::abs(partial - kk / nn * total) / std::sqrt(kk * (nn - kk) / nn) / scale;
      if (statistic > least && statistic / least > best) { best = statistic / least; at = k; }
    }
  }
  if (at < 0) return std::nullopt;
  const double before = observations[rows[static_cast<std::size_t>(at - 1)]].input.time_s;
  const double after = observations[rows[static_cast<std::size_t>(at)]].input.time_s;
  return 0.5 * (before + after);
}

}  // namespace gc
