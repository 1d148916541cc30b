#include "diagnosis/delay_estimate.h"

#include "diagnosis/time_step.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gc {
namespace {

constexpr double kEarliestS = -1.0, kLatestS = 2.0;
constexpr double kLeastGain = 0.01;  ///< a delay must remove this share of the summed squares

/// The summed squares of measured(t_i) - model(t_i - tau) over the rows, model interpolated in time.
double shifted_squares(const Eigen::VectorXd& t, const Eigen::MatrixX2d& measured, const Eigen::MatrixX2d& model,
                       double tau) {
  const Eigen::Index n = t.size();
  double sum = 0.0;
  Eigen::Index j = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double at = t(i) - tau;
    while (j + 1 < n && t(j + 1) <= at) ++j;
    while (j > 0 && t(j) > at) --j;
    Eigen::RowVector2d m = model.row(j);
    if (j + 1 < n && at > t(j) && t(j + 1) > t(j)) {
      const double w = std::min(1.0, (at - t(j)) / (t(j + 1) - t(j)));
      m = (1.0 - w) * model.row(j) + w * model.row(j + 1);
    }
    sum += (measured.row(i) - m).squaredNorm();
  }
  return sum;
}

}  // namespace

std::optional<double> moment_delay_estimate(std::span<const RecordedSample> observations,
                                            std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                            const ParallelFor& parallel) {
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  if (n < 8) return std::nullopt;
  Eigen::VectorXd t(n);
  Eigen::MatrixX2d measured(n, 2);
  for (Eigen::Index k = 0; k < n; ++k) {
    const RecordedSample& o = observations[rows[static_cast<std::size_t>(k)]];
    t(k) = o.input.time_s;
    measured.row(k) << o.measured.y_nm, o.measured.z_nm;
  }
  const Eigen::MatrixX2d model = measured - residual;
  const double step = 0.5 * typical_time_step(t);
  if (!(step > 0.0)) return std::nullopt;
  const double none = shifted_squares(t, measured, model, 0.0);
  std::vector<double> taus;
  for (double tau = kEarliestS; tau <= kLatestS + 1e-9; tau += step) taus.push_back(tau);
  // Every delay is a pass over the dense rows: a few hundred passes, on the diagnosis's path.
  std::vector<double> squares(taus.size());
  parallel(taus.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) squares[k] = shifted_squares(t, measured, model, taus[k]);
  });
  double best = none, best_tau = 0.0;
  for (std::size_t k = 0; k < taus.size(); ++k) {
    if (squares[k] < best) { best = squares[k]; best_tau = taus[k]; }
  }
  if (best_tau == 0.0 || best > (1.0 - kLeastGain) * none) return std::nullopt;
  return best_tau;
}

}  // namespace gc
