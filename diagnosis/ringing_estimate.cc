#include "diagnosis/ringing_estimate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "diagnosis/time_step.h"

namespace gc {
namespace {

constexpr double kLowestHz = 0.2;           ///< a mode rings a few times within a stair of seconds
constexpr double kHighestShareOfNyquist = 0.9;
constexpr double kFrequencyStep = 1.05;     ///< log spacing of the grid in f_n
constexpr double kDampings[] = {0.01, 0.015, 0.02, 0.03, 0.05, 0.07, 0.1, 0.14, 0.2};
constexpr double kFalseModeChance = 1e-3;   ///< of offering a mode in pure noise, whatever the grid
constexpr int kShifts = 19;                  ///< residuals shifted against the load: a 5 % test

/// What a mode's columns explain of the residual beside the nuisance, for every (f_n, zeta) asked.
class ModeScore {
 public:
  ModeScore(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
            const Eigen::MatrixX2d& residual)
      : rows_(rows.begin(), rows.end()) {
    for (const RecordedSample& o : observations) {
      times_.push_back(o.input.time_s);
      torques_.push_back(o.input.torque_nm);
    }
    const auto n = static_cast<Eigen::Index>(rows.size());
    Eigen::MatrixXd nuisance(n, 4);
    const double t0 = observations[rows.front()].input.time_s, span = observations[rows.back()].input.time_s - t0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const MeasurementSample& s = observations[rows[static_cast<std::size_t>(k)]].input;
      nuisance.row(k) << 1.0, (s.time_s - t0) / std::max(span, 1e-9), s.torque_nm, s.misalignment_rad;
    }
    // Columns alike in size, for the QR.
    for (Eigen::Index j = 0; j < nuisance.cols(); ++j) {
      const double size = nuisance.col(j).norm();
      if (size > 0.0) nuisance.col(j) /= size;
    }
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(nuisance);
    basis_ = qr.householderQ() * Eigen::MatrixXd::Identity(n, nuisance.cols());
    left_ = residual - basis_ * (basis_.transpose() * residual);
    // The residual turned round in time by kShifts lags, each less the nuisance again: noise keeps
    // its spectrum and loses any lock to the load's changes. The lags step by the golden ratio's
    // fraction of the rows (kept between a twentieth and nineteen twentieths), so that no two are a
    // staircase's period apart as evenly spread lags would be.
    for (int j = 1; j <= kShifts; ++j) {
      const double golden = std::fmod(0.6180339887498949 * j, 1.0);
      const Eigen::Index lag = static_cast<Eigen::Index>(static_cast<double>(n) * (0.05 + 0.9 * golden));
      Eigen::MatrixX2d turned(n, 2);
      turned.topRows(n - lag) = residual.bottomRows(n - lag);
      turned.bottomRows(lag) = residual.topRows(lag);
      shifted_.push_back(turned - basis_ * (basis_.transpose() * turned));
    }
  }

  /// The residual less the nuisance.
  const Eigen::MatrixX2d& left() const { return left_; }

  /// The summed squares the mode's ringing, one coefficient per channel, explains of left().
  double operator()(double f_hz, double zeta) const {
    const Eigen::VectorXd c = column(f_hz, zeta);
    const double cc = c.squaredNorm();
    return cc > 0.0 ? (c.transpose() * left_).squaredNorm() / cc : 0.0;
  }

  /// The same score on each residual shifted against the load.
  std::vector<double> shifted(double f_hz, double zeta) const {
    const Eigen::VectorXd c = column(f_hz, zeta);
    const double cc = c.squaredNorm();
    std::vector<double> out;
    for (const Eigen::MatrixX2d& s : shifted_) out.push_back(cc > 0.0 ? (c.transpose() * s).squaredNorm() / cc : 0.0);
    return out;
  }

  /// What the mode leaves of left().
  Eigen::MatrixX2d left_by(double f_hz, double zeta) const {
    const Eigen::VectorXd c = column(f_hz, zeta);
    const double cc = c.squaredNorm();
    if (!(cc > 0.0)) return left_;
    return left_ - c * (c.transpose() * left_) / cc;
  }

 private:
  /// The mode's ringing of the torque on the rows, less the nuisance.
  Eigen::VectorXd column(double f_hz, double zeta) const {
    const std::vector<double> r = ringing_sequence(times_, torques_, {f_hz, zeta});
    Eigen::VectorXd c(static_cast<Eigen::Index>(rows_.size()));
    for (std::size_t k = 0; k < rows_.size(); ++k) c(static_cast<Eigen::Index>(k)) = r[rows_[k]];
    return c - basis_ * (basis_.transpose() * c);
  }

  std::vector<std::size_t> rows_;
  std::vector<double> times_, torques_;
  Eigen::MatrixXd basis_;
  Eigen::MatrixX2d left_;
  std::vector<Eigen::MatrixX2d> shifted_;
};

/// Golden-section search for the best score of `f(x)` for x in [a, b].
template <typename F>
double golden_best(F f, double a, double b) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < 20; ++i) {
    if (fc > fd) { b = d; d = c; fd = fc; c = b - g * (b - a); fc = f(c); }
    else { a = c; c = d; fc = fd; d = a + g * (b - a); fd = f(d); }
  }
  return fc > fd ? c : d;
}

/// The lag-1 autocorrelation of `e`, both channels pooled, within [0, 0.95].
double lag_one_correlation(const Eigen::MatrixX2d& e) {
  const Eigen::Index n = e.rows();
  if (n < 3) return 0.0;
  const double products = (e.topRows(n - 1).array() * e.bottomRows(n - 1).array()).sum();
  return std::clamp(products / std::max(e.squaredNorm(), 1e-300), 0.0, 0.95);
}

}  // namespace

std::optional<RingingMode> dominant_ringing(std::span<const RecordedSample> observations,
                                            std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  if (n < 40) return std::nullopt;
  Eigen::VectorXd t(n);
  for (Eigen::Index k = 0; k < n; ++k) t(k) = observations[rows[static_cast<std::size_t>(k)]].input.time_s;
  const double dt = typical_time_step(t);
  if (!(dt > 0.0)) return std::nullopt;
  const double highest = kHighestShareOfNyquist * 0.5 / dt;
  const ModeScore score(observations, rows, residual);
  double best = 0.0, best_f = 0.0, best_zeta = 0.0;
  std::vector<double> best_shifted(kShifts, 0.0);  // the grid's best on each shifted residual
  int grid = 0;
  for (double f = kLowestHz; f <= highest; f *= kFrequencyStep) {
    for (const double zeta : kDampings) {
      ++grid;
      if (const double s = score(f, zeta); s > best) { best = s; best_f = f; best_zeta = zeta; }
      const std::vector<double> shifted = score.shifted(f, zeta);
      for (int j = 0; j < kShifts; ++j) best_shifted[j] = std::max(best_shifted[j], shifted[j]);
    }
  }
  if (!(best > 0.0)) return std::nullopt;  // the torque does not change
  // A ringing is set off by the load's changes: the grid must find more in the residual as it lies
  // than in any of it turned round in time against the load. Narrowband noise (a band-pass at 3.6
  // Hz, a resonance beside mains pickup) has its peak at every lag, and its spectrum hides from the
  // lag-1 inflation below.
  if (std::any_of(best_shifted.begin(), best_shifted.end(), [&](double s) { return s >= best; })) return std::nullopt;
  // Refined in f_n (log) and zeta between their grid neighbours, twice round.
  const double lowest_zeta = kDampings[0], highest_zeta = kDampings[std::size(kDampings) - 1];
  for (int round = 0; round < 2; ++round) {
    best_f = std::exp(golden_best([&](double lf) { return score(std::exp(lf), best_zeta); },
                                  std::log(best_f / kFrequencyStep), std::log(std::min(highest, best_f * kFrequencyStep))));
    best_zeta = golden_best([&](double z) { return score(best_f, z); }, std::max(lowest_zeta, best_zeta / 1.5),
                            std::min(highest_zeta, best_zeta * 1.5));
  }
  best = score(best_f, best_zeta);
  // Against the noise the mode leaves, correlated as it is: chi-square(2) per mode under the noise.
  const Eigen::MatrixX2d rest = score.left_by(best_f, best_zeta);
  const double variance = rest.squaredNorm() / static_cast<double>(2 * n - 10);
  const double phi = lag_one_correlation(rest);
  const double x = best / (variance * (1.0 + phi) / (1.0 - phi));
  if (grid * std::exp(-0.5 * x) >= kFalseModeChance) return std::nullopt;
  return RingingMode{best_f, best_zeta};
}

}  // namespace gc
