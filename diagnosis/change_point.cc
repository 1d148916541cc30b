#include "diagnosis/change_point.h"

#include "diagnosis/noise_estimate.h"

#include <algorithm>
#include <cmath>

namespace gc {
namespace {

constexpr Eigen::Index kFewestRows = 40;
/// The standardised CUSUM maximum that a single change must exceed, in units of the long-run
/// correlation of what the step leaves (sqrt of its variance inflation): the supremum of a
/// Brownian bridge over the middle 90 % exceeds 5 about once in a million (4 let the wander of a
/// random-walk zero through as a step once in the independent cases). Without it, the strongest wander of pure noise is
/// offered, and since its time was picked on every row, the cross-validation cannot reject it.
constexpr double kLeastStatistic = 5.0;
constexpr Eigen::Index kEdgeShare = 20;  ///< a change leaves at least 1/20 of the rows before it
/// ... and happens in the first 70 % of them: a term in time must predict the last fifth from what
/// comes before it (formula_search.cc), and a step that late is fitted on a few seconds after it,
/// which a wander of the zero fits as well (a random walk near the end was offered as a step).
constexpr double kLatestShare = 0.7;

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
    const Eigen::VectorXd x = e.col(c);
    // The strongest change of this channel (the CUSUM maximum over the middle rows) ...
    const double total = x.sum();
    double partial = 0.0, strongest = 0.0;
    Eigen::Index k_best = -1;
    for (Eigen::Index k = 1; k < n; ++k) {
      partial += x(k - 1);
      if (k < n / kEdgeShare || k > kLatestShare * static_cast<double>(n)) continue;
      const double kk = static_cast<double>(k), nn = static_cast<double>(n);
      const double cusum = std::abs(partial - kk / nn * total) / std::sqrt(kk * (nn - kk) / nn);
      if (cusum > strongest) { strongest = cusum; k_best = k; }
    }
    if (k_best < 0) continue;
    // ... judged against what is left once that one step is taken out: its scale and its long-run
    // inflation (the noise's correlation of any length). A real step leaves noise; a wandering
    // zero (a random walk) leaves a wander whose long-run variance dwarfs the step's statistic.
    Eigen::VectorXd left = x;
    left.head(k_best).array() -= left.head(k_best).mean();
    left.tail(n - k_best).array() -= left.tail(n - k_best).mean();
    const double scale = left.norm() / std::sqrt(static_cast<double>(n));
    if (!(scale > 0.0)) continue;
    const double statistic = strongest / scale / std::sqrt(long_run_inflation(left));
    if (statistic > kLeastStatistic && statistic / kLeastStatistic > best) {
      best = statistic / kLeastStatistic;
      at = k_best;
    }
  }
  if (at < 0) return std::nullopt;
  const double before = observations[rows[static_cast<std::size_t>(at - 1)]].input.time_s;
  const double after = observations[rows[static_cast<std::size_t>(at)]].input.time_s;
  return 0.5 * (before + after);
}

}  // namespace gc
