#include "diagnosis/ringing_estimate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <optional>
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
constexpr double kUnitRoundOff = 0x1p-53;
constexpr std::size_t kFrequenciesAtOnce = 6;  ///< 54 columns: 8.6 MB on 20,000 rows

/// A grid point's score on the residual, then on each of it shifted against the load.
using GridScores = std::array<double, kShifts + 1>;

/// Whether, and how, grid scores are found on the shifted residuals too.
enum class Shifts { none, fast, exact };

/// What a mode's columns explain of the residual beside the nuisance, for every (f_n, zeta) asked.
class ModeScore {
 public:
  ModeScore(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
            const Eigen::MatrixX2d& residual)
      : rows_(rows.begin(), rows.end()), rows_in_order_(std::is_sorted(rows.begin(), rows.end())) {
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
    stacked_.resize(n, 2 * kShifts);
    const double gamma = static_cast<double>(n) * kUnitRoundOff / (1.0 - static_cast<double>(n) * kUnitRoundOff);
    for (int j = 0; j < kShifts; ++j) {
      stacked_.middleCols(2 * j, 2) = shifted_[static_cast<std::size_t>(j)];
      tolerances_.push_back(16.0 * gamma * shifted_[static_cast<std::size_t>(j)].squaredNorm());
    }
  }

  /// The residual less the nuisance.
  const Eigen::MatrixX2d& left() const { return left_; }

  /// The summed squares the mode's ringing, one coefficient per channel, explains of left().
  double operator()(double f_hz, double zeta) const {
    if (const std::optional<double> score = streamed(f_hz, zeta)) return *score;
    const Eigen::VectorXd c = column(f_hz, zeta);
    return explained(c, c.squaredNorm(), left_);
  }

  /// For each frequency, for each damping of kDampings: the score (index 0) and the same score on
  /// each residual shifted against the load (1..kShifts; zero with Shifts::none). The scores are
  /// exactly operator()'s. The shifted ones are, with Shifts::exact; with Shifts::fast they come
  /// from one matrix product of all the columns with all the shifted residuals, several times
  /// faster (a few frequencies at a time share the packing of the shifted residuals), each within
  /// shift_tolerance() of its exact value (summed in another order).
  std::vector<std::vector<GridScores>> grid_scores(std::span<const double> frequencies, Shifts shifts) const {
    if (shifts == Shifts::none) return residual_scores(frequencies);
    std::vector<Eigen::VectorXd> columns;
    std::vector<double> squares;
    for (const double f_hz : frequencies) {
      for (const double zeta : kDampings) {
        columns.push_back(column(f_hz, zeta));
        squares.push_back(columns.back().squaredNorm());
      }
    }
    std::vector<GridScores> out(columns.size(), GridScores{});
    for (std::size_t m = 0; m < columns.size(); ++m) out[m][0] = explained(columns[m], squares[m], left_);
    if (shifts == Shifts::exact) {
      for (int j = 0; j < kShifts; ++j) {
        for (std::size_t m = 0; m < columns.size(); ++m) out[m][j + 1] = explained(columns[m], squares[m], shifted_[j]);
      }
    } else if (shifts == Shifts::fast) {
      Eigen::MatrixXd all(left_.rows(), static_cast<Eigen::Index>(columns.size()));
      for (std::size_t m = 0; m < columns.size(); ++m) all.col(static_cast<Eigen::Index>(m)) = columns[m];
      const Eigen::MatrixXd products = all.transpose() * stacked_;
      for (std::size_t m = 0; m < columns.size(); ++m) {
        const auto row = products.row(static_cast<Eigen::Index>(m));
        for (int j = 0; j < kShifts; ++j) {
          out[m][j + 1] = squares[m] > 0.0 ? (row(2 * j) * row(2 * j) + row(2 * j + 1) * row(2 * j + 1)) / squares[m] : 0.0;
        }
      }
    }
    std::vector<std::vector<GridScores>> by_frequency;
    for (std::size_t i = 0; i < frequencies.size(); ++i) {
      by_frequency.emplace_back(out.begin() + static_cast<std::ptrdiff_t>(i * std::size(kDampings)),
                                out.begin() + static_cast<std::ptrdiff_t>((i + 1) * std::size(kDampings)));
    }
    return by_frequency;
  }

  /// How far a shifted score of grid_scores without exact_shifts can lie from its exact value, on
  /// shifted residual j, for any column. A dot product of n terms summed in any order is within
  /// gamma_n sum |c_i e_i| <= gamma_n |c| |e| of the true one (gamma_n = n u / (1 - n u), u the
  /// unit round-off); both ways of computing are, so they are within 2 gamma_n |c| |e| of each
  /// other, and a score (c.e_y)^2 + (c.e_z)^2 over |c|^2 within about 4 gamma_n (|e_y|^2 + |e_z|^2).
  /// Four times that, for the squares, the division and |c|^2 itself being rounded.
  double shift_tolerance(int j) const { return tolerances_[static_cast<std::size_t>(j)]; }

  /// What the mode leaves of left().
  Eigen::MatrixX2d left_by(double f_hz, double zeta) const {
    const Eigen::VectorXd c = column(f_hz, zeta);
    const double cc = c.squaredNorm();
    if (!(cc > 0.0)) return left_;
    return left_ - c * (c.transpose() * left_) / cc;
  }

 private:
  /// grid_scores without shifts: operator() at each point, no column kept.
  std::vector<std::vector<GridScores>> residual_scores(std::span<const double> frequencies) const {
    std::vector<std::vector<GridScores>> by_frequency;
    for (const double f_hz : frequencies) {
      std::vector<GridScores>& at = by_frequency.emplace_back(std::size(kDampings), GridScores{});
      for (std::size_t z = 0; z < std::size(kDampings); ++z) at[z][0] = (*this)(f_hz, kDampings[z]);
    }
    return by_frequency;
  }

  /// operator() in one pass over the ringing, without forming the column c less the nuisance,
  /// c_p = c - Q Q^T c (Q = basis_, the nuisance's 4 columns): left() is orthogonal to Q, so
  /// c_p . left = c . left, and |c_p|^2 = |c|^2 - |Q^T c|^2. Forming and projecting a column was
  /// half of the grid's time. nullopt where the rows are not in time order, or where c lies so
  /// near the nuisance that the difference of squares would lose the digits of |c_p|^2.
  std::optional<double> streamed(double f_hz, double zeta) const {
    if (!rows_in_order_) return std::nullopt;
    RingingPole pole({f_hz, zeta});
    std::complex<double> sum = 0.0;
    double cc = 0.0, c0 = 0.0, c1 = 0.0, c2 = 0.0, c3 = 0.0, cy = 0.0, cz = 0.0;
    const auto take = [&](double c, Eigen::Index k) {
      cc += c * c;
      c0 += c * basis_(k, 0);
      c1 += c * basis_(k, 1);
      c2 += c * basis_(k, 2);
      c3 += c * basis_(k, 3);
      cy += c * left_(k, 0);
      cz += c * left_(k, 1);
    };
    std::size_t k = 0;
    for (; k < rows_.size() && rows_[k] == 0; ++k) take(0.0, static_cast<Eigen::Index>(k));  // r_0 = 0
    for (std::size_t i = 1; i < times_.size() && k < rows_.size(); ++i) {
      const double r = pole.next(sum, times_[i] - times_[i - 1], torques_[i] - torques_[i - 1]);
      for (; k < rows_.size() && rows_[k] == i; ++k) take(r, static_cast<Eigen::Index>(k));
    }
    if (!(cc > 0.0)) return 0.0;
    const double projected = cc - (c0 * c0 + c1 * c1 + c2 * c2 + c3 * c3);
    if (!(projected > 1e-6 * cc)) return std::nullopt;
    return (cy * cy + cz * cz) / projected;
  }

  /// The mode's ringing of the torque on the rows, less the nuisance.
  Eigen::VectorXd column(double f_hz, double zeta) const {
    const std::vector<double> r = ringing_sequence(times_, torques_, {f_hz, zeta});
    Eigen::VectorXd c(static_cast<Eigen::Index>(rows_.size()));
    for (std::size_t k = 0; k < rows_.size(); ++k) c(static_cast<Eigen::Index>(k)) = r[rows_[k]];
    return c - basis_ * (basis_.transpose() * c);
  }

  /// What column c (of squared norm cc) explains of the two channels of e.
  static double explained(const Eigen::VectorXd& c, double cc, const Eigen::MatrixX2d& e) {
    return cc > 0.0 ? (c.transpose() * e).squaredNorm() / cc : 0.0;
  }

  std::vector<std::size_t> rows_;
  bool rows_in_order_;
  std::vector<double> times_, torques_;
  Eigen::MatrixXd basis_;
  Eigen::MatrixX2d left_;
  std::vector<Eigen::MatrixX2d> shifted_;
  Eigen::MatrixXd stacked_;          ///< shifted_ side by side, for one product with many columns
  std::vector<double> tolerances_;   ///< shift_tolerance
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
                                            std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                            const ParallelFor& parallel) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  if (n < 40) return std::nullopt;
  Eigen::VectorXd t(n);
  for (Eigen::Index k = 0; k < n; ++k) t(k) = observations[rows[static_cast<std::size_t>(k)]].input.time_s;
  const double dt = typical_time_step(t);
  if (!(dt > 0.0)) return std::nullopt;
  const double highest = kHighestShareOfNyquist * 0.5 / dt;
  const ModeScore score(observations, rows, residual);
  double best = 0.0, best_f = 0.0, best_zeta = 0.0;
  std::size_t grid = 0;
  std::vector<double> frequencies;
  for (double f = kLowestHz; f <= highest; f *= kFrequencyStep) frequencies.push_back(f);
  // Each frequency's scores on its own, over the threads; then taken in the grid's order, so that
  // the best and its ties do not depend on how the work was shared.
  const auto grid_scores = [&](Shifts shifts) {
    std::vector<std::vector<GridScores>> scores(frequencies.size());
    parallel(frequencies.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; i += kFrequenciesAtOnce) {
        const std::size_t count = std::min(kFrequenciesAtOnce, end - i);
        std::vector<std::vector<GridScores>> some =
            score.grid_scores(std::span<const double>(frequencies).subspan(i, count), shifts);
        std::move(some.begin(), some.end(), scores.begin() + static_cast<std::ptrdiff_t>(i));
      }
    });
    return scores;
  };
  // The residual's own scores first: most recordings have no mode out of the noise, and the
  // shifted residuals (38 products of each column, beside its 2 with the residual) are asked only
  // of one that stands out.
  for (const std::vector<GridScores>& at : grid_scores(Shifts::none)) {
    for (std::size_t z = 0; z < std::size(kDampings); ++z, ++grid) {
      if (at[z][0] > best) { best = at[z][0]; best_f = frequencies[grid / std::size(kDampings)]; best_zeta = kDampings[z]; }
    }
  }
  if (!(best > 0.0)) return std::nullopt;  // the torque does not change
  const double grid_best = best;
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
  if (static_cast<double>(grid) * std::exp(-0.5 * x) >= kFalseModeChance) return std::nullopt;
  // A ringing is set off by the load's changes: the grid must find more in the residual as it lies
  // than in any of it turned round in time against the load. Narrowband noise (a band-pass at 3.6
  // Hz, a resonance beside mains pickup) has its peak at every lag, and its spectrum hides from the
  // lag-1 inflation above. The shifted scores decide only whether one of their grid's bests
  // reaches the residual's grid best. Where one is within its tolerance of it, the fast products
  // cannot say: they are made again exactly, as one (f_n, zeta) at a time would make them.
  std::vector<double> best_shifted(kShifts, 0.0);  // the grid's best on each shifted residual
  const auto take_shifted = [&](const std::vector<std::vector<GridScores>>& scores) {
    std::fill(best_shifted.begin(), best_shifted.end(), 0.0);
    for (const std::vector<GridScores>& at : scores) {
      for (const GridScores& s : at) {
        for (int j = 0; j < kShifts; ++j) best_shifted[j] = std::max(best_shifted[j], s[j + 1]);
      }
    }
  };
  take_shifted(grid_scores(Shifts::fast));
  bool surely_reached = false, surely_not = true;
  for (int j = 0; j < kShifts; ++j) {
    surely_reached = surely_reached || best_shifted[j] - score.shift_tolerance(j) >= grid_best;
    surely_not = surely_not && best_shifted[j] + score.shift_tolerance(j) < grid_best;
  }
  if (!surely_reached && !surely_not) take_shifted(grid_scores(Shifts::exact));
  if (std::any_of(best_shifted.begin(), best_shifted.end(), [&](double s) { return s >= grid_best; })) return std::nullopt;
  return RingingMode{best_f, best_zeta};
}

}  // namespace gc
