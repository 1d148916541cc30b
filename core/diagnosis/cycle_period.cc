#include "core/diagnosis/cycle_period.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace gc {
namespace {

constexpr int kScannedPeriods = 60;
/// A period at which an input swings this share of its own variance (beyond its trend) is the test
/// sequence's rhythm: a residual that follows it is that input's effect, which the catalogue's
/// terms of the input say in physics, not a drift of the zero.
constexpr double kInputCycleShare = 0.2;

/// The inputs a drift could be confused with, one column each (absent ones left out).
Eigen::MatrixXd input_columns(std::span<const RecordedSample> observations, std::span<const std::size_t> rows) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  const MeasurementSample& first = observations[rows.front()].input;
  const bool speed = first.speed_rpm.has_value(), temperature = first.temperature_c.has_value();
  Eigen::MatrixXd x(n, 2 + speed + temperature);
  for (Eigen::Index k = 0; k < n; ++k) {
    const MeasurementSample& s = observations[rows[static_cast<std::size_t>(k)]].input;
    Eigen::Index c = 0;
    x(k, c++) = s.torque_nm;
    x(k, c++) = s.misalignment_rad;
    if (speed) x(k, c++) = s.speed_rpm.value_or(0.0);
    if (temperature) x(k, c++) = s.temperature_c.value_or(0.0);
  }
  return x;
}

/// What the columns of `x` leave of each column of `y` (least squares), in summed squares.
Eigen::ArrayXd left_over(const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
  const auto qr = x.colPivHouseholderQr();
  return (y - x * qr.solve(y)).colwise().squaredNorm().transpose().array();
}

}  // namespace

std::optional<double> dominant_cycle_period(std::span<const RecordedSample> observations,
                                            std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual) {
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  if (n < 8) return std::nullopt;
  Eigen::VectorXd t(n);
  for (Eigen::Index k = 0; k < n; ++k) t(k) = observations[rows[static_cast<std::size_t>(k)]].input.time_s;
  const double start = t.minCoeff(), span = t.maxCoeff() - start;
  const double shortest = std::max(2.0, span / kCyclesInSpanMost), longest = span / kCyclesInSpanLeast;
  if (!(longest > shortest)) return std::nullopt;
  // The trend: quadratic in time, on t scaled to [-1, 1] so the columns are alike.
  Eigen::MatrixXd trend(n, 5);
  const Eigen::ArrayXd u = 2.0 * (t.array() - start) / span - 1.0;
  trend.col(0).setOnes();
  trend.col(1) = u.matrix();
  trend.col(2) = (u * u).matrix();
  // The residual's nuisance adds the inputs, so that a cycle earns only what they do not explain.
  const Eigen::MatrixXd inputs = input_columns(observations, rows);
  Eigen::MatrixXd nuisance(n, 5 + inputs.cols());
  nuisance << trend.leftCols(3), inputs, Eigen::MatrixXd::Zero(n, 2);
  const Eigen::ArrayXd inputs_trend_only = left_over(trend.leftCols(3), inputs);
  const Eigen::ArrayXd residual_nuisance_only = left_over(nuisance.leftCols(nuisance.cols() - 2), residual);
  // The residual's summed squares the cycle explains; 0 where an input swings at the period.
  const auto gain = [&](double period) {
    const Eigen::ArrayXd angle = 2.0 * std::numbers::pi * t.array() / period;
    trend.col(3) = nuisance.col(nuisance.cols() - 2) = angle.sin().matrix();
    trend.col(4) = nuisance.col(nuisance.cols() - 1) = angle.cos().matrix();
    const Eigen::ArrayXd swing = inputs_trend_only - left_over(trend, inputs);
    if ((swing > kInputCycleShare * inputs_trend_only).any()) return 0.0;
    return (residual_nuisance_only - left_over(nuisance, residual)).sum();
  };
  // A geometric grid, then every whole second between the best point's neighbours.
  const double step = std::pow(longest / shortest, 1.0 / (kScannedPeriods - 1.0));
  std::optional<double> best;
  double best_gain = 0.0;
  for (int i = 0; i < kScannedPeriods; ++i) {
    const double period = shortest * std::pow(step, i);
    if (const double g = gain(period); g > best_gain) { best_gain = g; best = period; }
  }
  if (!best) return std::nullopt;
  const double around = *best;
  best.reset();
  best_gain = 0.0;
  for (double period = std::max(2.0, std::floor(around / step)); period <= std::ceil(around * step); period += 1.0) {
    if (const double g = gain(period); g > best_gain) { best_gain = g; best = period; }
  }
  return best;
}

}  // namespace gc
