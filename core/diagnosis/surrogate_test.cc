#include "core/diagnosis/surrogate_test.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <array>

#include <unsupported/Eigen/FFT>

namespace gc {
namespace {

/// The variance of a rise from the first row to the last: the increments' power at the lowest
/// frequencies (their sum is the rise). A random walk's increments are white, and it rises by
/// about its step times the root of its length; a stationary noise's increments have next to no
/// power there, and it rises by little.
double increments_low_power(const Eigen::VectorXd& x) {
  const Eigen::Index m = x.size() - 1;
  if (m < 8) return 0.0;
  const Eigen::VectorXd d = x.tail(m) - x.head(m);
  double power = 0.0;
  for (int k = 1; k <= 3; ++k) {
    std::complex<double> sum = 0.0;
    for (Eigen::Index j = 0; j < m; ++j) sum += d(j) * std::polar(1.0, -2.0 * std::numbers::pi * k * j / static_cast<double>(m));
    power = std::max(power, std::norm(sum));
  }
  return power;
}

/// A bin this many times the median power about it is a line (a cycle, or a test programme that
/// repeats), not the noise's continuum.
constexpr double kLineRatio = 10.0;

/// `spectrum`'s amplitudes for k = 0..n/2, each line brought down to the median about it (bins
/// k/2..2k): a surrogate keeps the noise's continuum but not a line, which a design in phase with
/// it would otherwise explain in many surrogates as well as in the residual (a hysteresis on
/// repeated misalignment sweeps lost its claim that way).
std::vector<double> without_lines(const std::vector<std::complex<double>>& spectrum) {
  const std::size_t half = spectrum.size() / 2;
  std::vector<double> power(half + 1), amplitude(half + 1);
  for (std::size_t k = 0; k <= half; ++k) power[k] = std::norm(spectrum[k]);
  for (std::size_t k = 0; k <= half; ++k) {
    amplitude[k] = std::sqrt(power[k]);
    if (k == 0) continue;
    std::vector<double> about(power.begin() + static_cast<std::ptrdiff_t>(std::max<std::size_t>(1, k / 2)),
                              power.begin() + static_cast<std::ptrdiff_t>(std::min(half, 2 * k) + 1));
    if (about.size() < 5) continue;
    std::nth_element(about.begin(), about.begin() + static_cast<std::ptrdiff_t>(about.size() / 2), about.end());
    const double median = about[about.size() / 2];
    if (power[k] > kLineRatio * median) amplitude[k] = std::sqrt(median);
  }
  return amplitude;
}

/// The largest length up to `n` whose only prime factors are 2, 3 and 5.
Eigen::Index smooth_length(Eigen::Index n) {
  for (Eigen::Index m = n; m > 1; --m) {
    Eigen::Index r = m;
    for (const Eigen::Index f : {2, 3, 5}) {
      while (r % f == 0) r /= f;
    }
    if (r == 1) return m;
  }
  return 1;
}

Eigen::VectorXd stacked(const Eigen::MatrixX2d& m) {
  Eigen::VectorXd y(2 * m.rows());
  y << m.col(0), m.col(1);
  return y;
}

/// One design made ready to project many right-hand sides.
class Projector {
 public:
  /// `rows`: the rows of each channel (the design has 2 * rows).
  Projector(const SurrogateDesign& design, Eigen::Index rows) : choose_(design.choose), levels_(levels(rows)) {
    if (choose_ <= 0) {
      basis_ = orthonormal(concatenated(levels_, design.columns));
      return;
    }
    normalised_ = design.columns;
    normalised_ -= levels_ * (levels_.transpose() * normalised_);
    for (Eigen::Index j = 0; j < normalised_.cols(); ++j) {
      const double norm = normalised_.col(j).norm();
      const double before = design.columns.col(j).norm();
      // A term some row cannot evaluate, or a level, is never chosen.
      if (std::isfinite(norm) && norm > 1e-9 * before) {
        normalised_.col(j) /= norm;
      } else {
        normalised_.col(j).setZero();
      }
    }
  }

  /// The share of what varies about each channel's level that the design explains beyond it.
  double share(const Eigen::VectorXd& y) const {
    const double level = (levels_.transpose() * y).squaredNorm();
    const double total = y.squaredNorm() - level;
    if (!(total > 0.0)) return 0.0;
    const double fit = choose_ <= 0 ? (basis_.transpose() * y).squaredNorm() : greedy_fit(y).squaredNorm();
    return std::clamp((fit - level) / total, 0.0, 1.0);
  }

 private:
  /// Orthogonal matching pursuit: `choose_` steps, each taking the column most correlated with
  /// what the chosen ones leave; returns the fit.
  Eigen::VectorXd greedy_fit(const Eigen::VectorXd& y) const {
    const Eigen::Index steps = std::min<Eigen::Index>(choose_, normalised_.cols());
    Eigen::MatrixXd basis(y.size(), levels_.cols() + steps);
    basis.leftCols(levels_.cols()) = levels_;
    Eigen::Index kept = levels_.cols();
    Eigen::VectorXd left = y - basis.leftCols(kept) * (basis.leftCols(kept).transpose() * y);
    std::vector<bool> taken(static_cast<std::size_t>(normalised_.cols()), false);
    for (Eigen::Index step = 0; step < steps; ++step) {
      const Eigen::VectorXd scores = (normalised_.transpose() * left).cwiseAbs();
      Eigen::Index best = -1;
      for (Eigen::Index j = 0; j < scores.size(); ++j) {
        if (!taken[static_cast<std::size_t>(j)] && (best < 0 || scores(j) > scores(best))) best = j;
      }
      if (best < 0) break;
      taken[static_cast<std::size_t>(best)] = true;
      Eigen::VectorXd q = normalised_.col(best);
      for (int pass = 0; pass < 2; ++pass) q -= basis.leftCols(kept) * (basis.leftCols(kept).transpose() * q);
      const double norm = q.norm();
      if (!(norm > 1e-9)) continue;
      basis.col(kept++) = q / norm;
      left = y - basis.leftCols(kept) * (basis.leftCols(kept).transpose() * y);
    }
    return y - left;
  }

  /// Each channel's level, as orthonormal columns.
  static Eigen::MatrixXd levels(Eigen::Index rows) {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(2 * rows, 2);
    const double unit = 1.0 / std::sqrt(static_cast<double>(std::max<Eigen::Index>(rows, 1)));
    out.col(0).head(rows).setConstant(unit);
    out.col(1).tail(rows).setConstant(unit);
    return out;
  }

  static Eigen::MatrixXd concatenated(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    Eigen::MatrixXd out(a.rows(), a.cols() + b.cols());
    out << a, b;
    return out;
  }

  /// Orthonormal columns spanning `m`'s finite columns.
  static Eigen::MatrixXd orthonormal(Eigen::MatrixXd m) {
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (!m.col(j).allFinite()) m.col(j).setZero();
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
    return qr.householderQ() * Eigen::MatrixXd::Identity(m.rows(), qr.rank());
  }

  int choose_;
  Eigen::MatrixXd levels_;      ///< each channel's level, orthonormal
  Eigen::MatrixXd basis_;       ///< orthonormal columns spanning the levels and the design (choose_ 0)
  Eigen::MatrixXd normalised_;  ///< unit columns, less the levels (choose_ > 0)
};

}  // namespace

std::vector<Eigen::MatrixX2d> phase_randomised_surrogates(const Eigen::MatrixX2d& residual, int count,
                                                          std::uint64_t seed) {
  const Eigen::Index n = residual.rows();
  std::vector<Eigen::MatrixX2d> out;
  if (n < 8 || count <= 0) return out;
  // The FFT's length has only the factors 2, 3 and 5 (a prime length costs n^2): the last m rows;
  // a surrogate is circular, so it wraps to the n rows.
  const Eigen::Index m = smooth_length(n);
  Eigen::FFT<double> fft;
  std::array<std::vector<double>, 2> amplitudes;
  std::array<double, 2> rise_power{};
  for (int c = 0; c < 2; ++c) {
    // End-matched: less the line from its first to its last value, which a circular surrogate
    // cannot hold; a rise of its own is drawn for each surrogate instead (rise_power).
    Eigen::VectorXd tail = residual.col(c).tail(m);
    const double first = tail(0), last = tail(m - 1);
    for (Eigen::Index i = 0; i < m; ++i) tail(i) -= first + (last - first) * static_cast<double>(i) / static_cast<double>(m - 1);
    std::vector<std::complex<double>> spectrum;
    fft.fwd(spectrum, std::vector<double>(tail.data(), tail.data() + m));
    amplitudes[static_cast<std::size_t>(c)] = without_lines(spectrum);
    rise_power[static_cast<std::size_t>(c)] = increments_low_power(residual.col(c));
  }
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  std::normal_distribution<double> normal;
  std::vector<std::complex<double>> turned(static_cast<std::size_t>(m));
  std::vector<double> back;
  for (int s = 0; s < count; ++s) {
    std::vector<std::complex<double>> rotation(static_cast<std::size_t>(m / 2 + 1));
    for (Eigen::Index k = 1; k <= m / 2; ++k) rotation[static_cast<std::size_t>(k)] = std::polar(1.0, phase(random));
    Eigen::MatrixX2d surrogate(n, 2);
    for (int c = 0; c < 2; ++c) {
      const std::vector<double>& x = amplitudes[static_cast<std::size_t>(c)];
      turned[0] = 0.0;  // the level is not judged (Projector::share)
      for (Eigen::Index k = 1; k <= (m - 1) / 2; ++k) {
        const std::complex<double> v = x[static_cast<std::size_t>(k)] * rotation[static_cast<std::size_t>(k)];
        turned[static_cast<std::size_t>(k)] = v;
        turned[static_cast<std::size_t>(m - k)] = std::conj(v);
      }
      if (m % 2 == 0) {
        turned[static_cast<std::size_t>(m / 2)] =
            x[static_cast<std::size_t>(m / 2)] * (rotation[static_cast<std::size_t>(m / 2)].real() < 0.0 ? -1.0 : 1.0);
      }
      fft.inv(back, turned);
      const double rise = normal(random) * std::sqrt(rise_power[static_cast<std::size_t>(c)]);
      for (Eigen::Index i = 0; i < n; ++i) {
        surrogate(i, c) = back[static_cast<std::size_t>(i % m)] + rise * (static_cast<double>(i) / static_cast<double>(n - 1) - 0.5);
      }
    }
    out.push_back(std::move(surrogate));
  }
  return out;
}

double explained_share(const SurrogateDesign& design, const Eigen::MatrixX2d& residual) {
  return Projector(design, residual.rows()).share(stacked(residual));
}

double level_p_value(const Eigen::MatrixX2d& residual) {
  double p = 1.0;
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd x = residual.col(c);
    const Eigen::Index n = x.size(), parts = 5;
    if (n < parts) continue;
    Eigen::VectorXd means(parts);
    for (Eigen::Index k = 0; k < parts; ++k) means(k) = x.segment(k * n / parts, (k + 1) * n / parts - k * n / parts).mean();
    const double spread = std::sqrt((means.array() - means.mean()).square().sum() / (parts - 1.0));
    const double t = spread > 0.0 ? std::abs(x.mean()) / spread : (x.mean() != 0.0 ? 1e300 : 0.0);
    // Student's t with 4 degrees of freedom, two-sided: 1 - F(t) + F(-t), x = t / sqrt(t^2 + 4).
    const double u = t / std::sqrt(t * t + 4.0);
    p = std::min(p, std::clamp(1.0 - 1.5 * u + 0.5 * u * u * u, 0.0, 1.0));
  }
  return std::min(1.0, 2.0 * p);  // either channel
}

std::vector<double> surrogate_p_values(const Eigen::MatrixX2d& residual, const std::vector<SurrogateDesign>& designs,
                                       double level, std::uint64_t seed) {
  std::vector<double> adjusted(designs.size(), 1.0);
  if (designs.empty() || !(level > 0.0)) return adjusted;
  const double family = static_cast<double>(designs.size());
  // Enough surrogates that the smallest p-value, times the family and the two parts of a design
  // (what varies, its level), is half the level.
  const int count = std::max(199, static_cast<int>(std::ceil(4.0 * family / level)) - 1);
  // Besag and Clifford's sequential stop: once this many surrogates are explained as well, the
  // p-value is above level / (2 family) whatever the rest say.
  const int enough = static_cast<int>(std::ceil(level / (2.0 * family) * (count + 1.0)));
  const Eigen::VectorXd y = stacked(residual);
  // Under the null the residual is the noise: its own spectrum, no relation to the inputs. Every
  // design is judged on the same surrogates.
  const std::vector<Eigen::MatrixX2d> surrogates = phase_randomised_surrogates(residual, count, seed);
  const double level_p = level_p_value(residual);
  for (std::size_t d = 0; d < designs.size(); ++d) {
    double p = 1.0;
    if (designs[d].columns.cols() > 0) {
      const Projector projector(designs[d], residual.rows());
      const double observed = projector.share(y);
      int as_well = 0, drawn = 0;
      for (const Eigen::MatrixX2d& s : surrogates) {
        ++drawn;
        if (projector.share(stacked(s)) >= observed && ++as_well >= enough) break;
      }
      p = as_well >= enough ? 1.0 : (1.0 + as_well) / (1.0 + static_cast<double>(drawn));
    }
    if (designs[d].level) p = std::min(p, level_p);
    adjusted[d] = std::min(1.0, 2.0 * family * p);
  }
  return adjusted;
}

}  // namespace gc
