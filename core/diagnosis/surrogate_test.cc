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

/// The lowest frequencies whose power stands for the power at zero frequency: a few bins, more on
/// a long recording, where each bin is narrower.
std::size_t low_bins(std::size_t n) { return std::clamp<std::size_t>(n / 200, 3, std::max<std::size_t>(3, n / 2 - 1)); }

/// The most power of the lowest frequencies of `spectrum`: a wander whose time scale is a good part
/// of the recording has more power at zero frequency than at the first bins (an Ornstein-Uhlenbeck
/// zero of tau 12 s over 28 s left a 3 kN·m level that their mean called an offset).
double low_frequency_power(const std::vector<std::complex<double>>& spectrum) {
  double power = 0.0;
  const std::size_t bins = std::min(low_bins(spectrum.size()), spectrum.size() / 2);
  for (std::size_t k = 1; k <= bins; ++k) power = std::max(power, std::norm(spectrum[k]));
  return power;
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
  explicit Projector(const SurrogateDesign& design) : choose_(design.choose) {
    if (design.forced.cols() > 0) forced_ = orthonormal(design.forced);
    if (choose_ <= 0) {
      basis_ = orthonormal(design.forced.cols() > 0 ? concatenated(design.forced, design.columns) : design.columns);
      return;
    }
    normalised_ = design.columns;
    if (forced_.cols() > 0) normalised_ -= forced_ * (forced_.transpose() * normalised_);
    for (Eigen::Index j = 0; j < normalised_.cols(); ++j) {
      const double norm = normalised_.col(j).norm();
      const double before = design.columns.col(j).norm();
      // A term some row cannot evaluate, or one the forced columns already span, is never chosen.
      if (std::isfinite(norm) && norm > 1e-9 * before) {
        normalised_.col(j) /= norm;
      } else {
        normalised_.col(j).setZero();
      }
    }
  }

  double share(const Eigen::VectorXd& y) const {
    const double total = y.squaredNorm();
    if (!(total > 0.0)) return 0.0;
    if (choose_ <= 0) return std::min(1.0, (basis_.transpose() * y).squaredNorm() / total);
    return std::min(1.0, fitted(y).squaredNorm() / total);
  }

  /// The least-squares fit of `y` on the design (on the columns chosen for `y`).
  Eigen::VectorXd fitted(const Eigen::VectorXd& y) const {
    if (choose_ <= 0) return basis_ * (basis_.transpose() * y);
    return greedy_fit(y);
  }

 private:
  /// Orthogonal matching pursuit: `choose_` steps, each taking the column most correlated with
  /// what the chosen ones leave; returns the fit.
  Eigen::VectorXd greedy_fit(const Eigen::VectorXd& y) const {
    const Eigen::Index steps = std::min<Eigen::Index>(choose_, normalised_.cols());
    Eigen::MatrixXd basis(y.size(), forced_.cols() + steps);
    basis.leftCols(forced_.cols()) = forced_;
    Eigen::Index kept = forced_.cols();
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
  Eigen::MatrixXd basis_;       ///< orthonormal columns spanning the design (choose_ 0)
  Eigen::MatrixXd normalised_;  ///< unit columns, less what forced_ spans (choose_ > 0)
  Eigen::MatrixXd forced_;      ///< orthonormal columns spanning the forced ones
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
  std::array<std::vector<std::complex<double>>, 2> spectra;
  std::array<double, 2> level_power{};
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd tail = residual.col(c).tail(m);
    fft.fwd(spectra[static_cast<std::size_t>(c)], std::vector<double>(tail.data(), tail.data() + m));
    level_power[static_cast<std::size_t>(c)] = low_frequency_power(spectra[static_cast<std::size_t>(c)]);
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
      const auto& x = spectra[static_cast<std::size_t>(c)];
      turned[0] = normal(random) * std::sqrt(level_power[static_cast<std::size_t>(c)]);
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
      for (Eigen::Index i = 0; i < n; ++i) surrogate(i, c) = back[static_cast<std::size_t>(i % m)];
    }
    out.push_back(std::move(surrogate));
  }
  return out;
}

double explained_share(const SurrogateDesign& design, const Eigen::MatrixX2d& residual) {
  return Projector(design).share(stacked(residual));
}

std::vector<double> surrogate_p_values(const Eigen::MatrixX2d& residual, const std::vector<SurrogateDesign>& designs,
                                       double level, std::uint64_t seed) {
  std::vector<double> adjusted(designs.size(), 1.0);
  if (designs.empty() || !(level > 0.0)) return adjusted;
  const double family = static_cast<double>(designs.size());
  // Enough surrogates that the smallest p-value, times the family, is half the level.
  const int count = std::max(199, static_cast<int>(std::ceil(2.0 * family / level)) - 1);
  // Besag and Clifford's sequential stop: once this many surrogates are explained as well, the
  // p-value is above level / family whatever the rest say.
  const int enough = static_cast<int>(std::ceil(level / family * (count + 1.0)));
  const Eigen::VectorXd y = stacked(residual);
  // Under the null the residual is the noise: its own spectrum, no relation to the inputs. Every
  // design is judged on the same surrogates.
  const std::vector<Eigen::MatrixX2d> all_surrogates = phase_randomised_surrogates(residual, count, seed);
  for (std::size_t d = 0; d < designs.size(); ++d) {
    const Projector projector(designs[d]);
    const double observed = projector.share(y);
    const std::vector<Eigen::MatrixX2d>& surrogates = all_surrogates;
    int as_well = 0, drawn = 0;
    for (const Eigen::MatrixX2d& s : surrogates) {
      ++drawn;
      if (projector.share(stacked(s)) >= observed && ++as_well >= enough) break;
    }
    const double p = as_well >= enough ? 1.0 : (1.0 + as_well) / (1.0 + static_cast<double>(drawn));
    adjusted[d] = std::min(1.0, family * p);
  }
  return adjusted;
}

}  // namespace gc
