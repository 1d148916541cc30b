#include "diagnosis/cycle_period.h"

#include "diagnosis/median.h"
#include "diagnosis/time_step.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <unsupported/Eigen/FFT>

namespace gc {
namespace {

/// Peaks of the periodogram scored exactly: a few, since a cycle worth offering stands out.
constexpr int kPeaksScored = 4;
constexpr std::size_t kLocalBins = 60;   ///< either side, for the local level of the periodogram
constexpr double kFalsePeakChance = 1e-3;  ///< of offering a cycle in pure noise, whatever the scan
/// A period at which an input swings this share of its own variance (beyond its trend) is the test
/// sequence's rhythm: a residual that follows it is that input's effect, which the catalogue's
/// terms of the input say in physics, not a drift of the zero.
constexpr double kInputCycleShare = 0.2;

/// The inputs a cycle could be confused with, one column each (absent ones left out).
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

/// An orthonormal basis of the columns of `x` (thin Q), to project many columns cheaply.
Eigen::MatrixXd orthonormal_basis(const Eigen::MatrixXd& x) {
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(x);
  return qr.householderQ() * Eigen::MatrixXd::Identity(x.rows(), x.cols());
}

/// Per column of `y`, the summed squares the columns of `a` (n x 2) explain.
Eigen::ArrayXd explained(const Eigen::MatrixXd& a, const Eigen::MatrixXd& y) {
  const Eigen::MatrixXd ay = a.transpose() * y;
  const Eigen::MatrixXd solved = (a.transpose() * a).ldlt().solve(ay);
  return (ay.array() * solved.array()).colwise().sum().transpose();
}

/// The exact score of a period: the residual's summed squares that its sine and cosine explain
/// beside the nuisance (a quadratic trend and the inputs), or 0 where an input swings at it.
class PeriodScore {
 public:
  PeriodScore(const Eigen::VectorXd& t, const Eigen::MatrixXd& inputs, const Eigen::MatrixX2d& residual) : t_(t) {
    const Eigen::Index n = t.size();
    const double start = t.minCoeff(), span = t.maxCoeff() - start;
    const Eigen::ArrayXd u = 2.0 * (t.array() - start) / span - 1.0;  // columns alike in size
    Eigen::MatrixXd trend(n, 3);
    trend << Eigen::VectorXd::Ones(n), u.matrix(), (u * u).matrix();
    Eigen::MatrixXd nuisance(n, 3 + inputs.cols());
    nuisance << trend, inputs;
    trend_basis_ = orthonormal_basis(trend);
    nuisance_basis_ = orthonormal_basis(nuisance);
    inputs_left_ = inputs - trend_basis_ * (trend_basis_.transpose() * inputs);
    inputs_left_squares_ = inputs_left_.colwise().squaredNorm().transpose().array();
    residual_left_ = residual - nuisance_basis_ * (nuisance_basis_.transpose() * residual);
  }

  /// What the nuisance leaves of the residual.
  const Eigen::MatrixXd& residual_left() const { return residual_left_; }

  double operator()(double period) const {
    const Eigen::ArrayXd angle = 2.0 * std::numbers::pi * t_.array() / period;
    Eigen::MatrixXd wave(t_.size(), 2);
    wave << angle.sin().matrix(), angle.cos().matrix();
    const Eigen::MatrixXd beside_trend = wave - trend_basis_ * (trend_basis_.transpose() * wave);
    if (inputs_left_.cols() > 0 &&
        (explained(beside_trend, inputs_left_) > kInputCycleShare * inputs_left_squares_).any()) {
      return 0.0;
    }
    const Eigen::MatrixXd beside_nuisance = wave - nuisance_basis_ * (nuisance_basis_.transpose() * wave);
    return explained(beside_nuisance, residual_left_).sum();
  }

 private:
  Eigen::VectorXd t_;
  Eigen::MatrixXd trend_basis_, nuisance_basis_, inputs_left_, residual_left_;
  Eigen::ArrayXd inputs_left_squares_;
};

/// The summed power of both channels of `e` (rows at times t) per frequency bin of a uniform grid of
/// spacing dt, zero-padded to at least twice its length. Bin j is the frequency j / (L dt).
std::vector<double> periodogram(const Eigen::VectorXd& t, const Eigen::MatrixX2d& e, double dt, std::size_t& length) {
  const double start = t.minCoeff();
  const auto cells = static_cast<std::size_t>(std::floor((t.maxCoeff() - start) / dt)) + 1;
  length = 1;
  while (length < 2 * cells) length *= 2;
  std::vector<double> power(length / 2 + 1, 0.0);
  Eigen::FFT<double> fft;
  for (int c = 0; c < 2; ++c) {
    std::vector<double> sum(length, 0.0), count(length, 0.0);
    for (Eigen::Index k = 0; k < t.size(); ++k) {
      const auto cell = std::min(cells - 1, static_cast<std::size_t>(std::lround((t(k) - start) / dt)));
      sum[cell] += e(k, c);
      count[cell] += 1.0;
    }
    for (std::size_t i = 0; i < cells; ++i) if (count[i] > 0.0) sum[i] /= count[i];
    std::vector<std::complex<double>> spectrum;
    fft.fwd(spectrum, sum);
    for (std::size_t j = 0; j < power.size(); ++j) power[j] += std::norm(spectrum[j]);
  }
  return power;
}

/// The periodogram's level around bin j: the median of the bins within `kLocalBins` of it, those
/// within 2 (the peak's own leakage) left out. The median follows coloured noise, whose level falls
/// with frequency, where a global level would call every low-frequency bin a peak.
double local_level(const std::vector<double>& power, std::size_t j, std::size_t first, std::size_t last) {
  std::vector<double> around;
  const std::size_t from = j > first + kLocalBins ? j - kLocalBins : first;
  const std::size_t to = std::min(last, j + kLocalBins);
  for (std::size_t k = from; k <= to; ++k) if (k + 2 < j || k > j + 2) around.push_back(power[k]);
  return median(std::move(around));
}

/// A peak stands out of the noise when its power over the local level exceeds what the largest of
/// `independent` noise bins reaches once in a thousand: a bin of two channels' noise is about
/// Gamma(2) (median 1.678), P(> x) = (1 + x) e^-x. Without it, the largest of thousands of bins of
/// pure noise is offered, and since its period was picked on every row, held-out rows included,
/// the cross-validation cannot reject it.
bool stands_out(double power, double level, double independent) {
  if (!(level > 0.0)) return power > 0.0;
  const double x = 1.678 * power / level;
  return independent * (1.0 + x) * std::exp(-x) < kFalsePeakChance;
}

/// The bins of the `count` largest local maxima of `power` within [first, last].
std::vector<std::size_t> strongest_peaks(const std::vector<double>& power, std::size_t first, std::size_t last, int count) {
  std::vector<std::size_t> peaks;
  for (std::size_t j = std::max<std::size_t>(first, 1); j <= last && j + 1 < power.size(); ++j) {
    if (power[j] >= power[j - 1] && power[j] >= power[j + 1]) peaks.push_back(j);
  }
  const auto keep = std::min<std::size_t>(static_cast<std::size_t>(count), peaks.size());
  std::partial_sort(peaks.begin(), peaks.begin() + static_cast<std::ptrdiff_t>(keep), peaks.end(),
                    [&](std::size_t a, std::size_t b) { return power[a] > power[b]; });
  peaks.resize(keep);
  return peaks;
}

/// Golden-section search for the best score between periods a and b.
double refine(const PeriodScore& score, double a, double b) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = score(c), fd = score(d);
  for (int i = 0; i < 24 && (b - a) > 1e-9 * b; ++i) {
    if (fc > fd) { b = d; d = c; fd = fc; c = b - g * (b - a); fc = score(c); }
    else { a = c; c = d; fc = fd; d = a + g * (b - a); fd = score(d); }
  }
  return fc > fd ? c : d;
}

}  // namespace

std::optional<double> dominant_cycle_period(std::span<const RecordedSample> observations,
                                            std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                            const ParallelFor& parallel) {
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  if (n < 8) return std::nullopt;
  Eigen::VectorXd t(n);
  for (Eigen::Index k = 0; k < n; ++k) t(k) = observations[rows[static_cast<std::size_t>(k)]].input.time_s;
  const double span = t.maxCoeff() - t.minCoeff(), dt = typical_time_step(t);
  if (!(dt > 0.0) || !(span > 4.0 * dt)) return std::nullopt;
  const double longest = span / kCyclesInSpanLeast;
  const PeriodScore score(t, input_columns(observations, rows), residual);
  const Eigen::MatrixX2d left = score.residual_left();
  std::size_t length = 0;
  const std::vector<double> power = periodogram(t, left, dt, length);
  const double bin_hz = 1.0 / (static_cast<double>(length) * dt);
  const auto first = static_cast<std::size_t>(std::ceil(1.0 / (longest * bin_hz)));
  const auto last = std::min(power.size() - 2, static_cast<std::size_t>(std::floor(0.98 * 0.5 / (dt * bin_hz))));
  std::optional<double> best;
  double best_score = 0.0;
  // Zero-padded twice: neighbouring bins are not independent, half of them are.
  const double independent = 0.5 * static_cast<double>(last - std::min(first, last) + 1);
  std::vector<std::size_t> peaks;
  for (std::size_t j : strongest_peaks(power, first, last, kPeaksScored)) {
    if (stands_out(power[j], local_level(power, j, first, last), independent)) peaks.push_back(j);
  }
  // Each peak refined within one bin either side, in period: a few dozen exact scores of every row
  // each, side by side; then taken in the peaks' order, as one at a time would take them.
  std::vector<double> periods(peaks.size()), scores(peaks.size());
  parallel(peaks.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const double j = static_cast<double>(peaks[k]);
      const double low = 1.0 / ((j + 1.0) * bin_hz);
      const double high = std::min(longest, 1.0 / ((j - 1.0 + 1e-9) * bin_hz));
      periods[k] = refine(score, low, high);
      scores[k] = score(periods[k]);
    }
  });
  for (std::size_t k = 0; k < peaks.size(); ++k) {
    if (scores[k] > best_score) { best_score = scores[k]; best = periods[k]; }
  }
  return best;
}

}  // namespace gc
