#include "core/diagnosis/noise_estimate.h"

#include <algorithm>
#include <cmath>

namespace gc {
namespace {

constexpr int kMaxLag = 10;     ///< samples: beyond a few correlation times of most noise we meet
constexpr int kLongestLag = 100;  ///< samples: for noise of long correlation (phi >= kLongPhi)
constexpr double kLongPhi = 0.8;
constexpr double kLongStructureShare = 0.1;  ///< of the longest lag's semivariance
constexpr double kLongMisfitShare = 0.1;     ///< RMS misfit of the long fit over the mean semivariance
constexpr double kTailCap = 20.0;  ///< t(2)-like tails: beyond this the mean square says little
constexpr int kMedianHalf = 3;  ///< running median over 7 samples

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

/// Robust half mean square of the lag-h differences: (1.4826 MAD)^2 / 2, centred on zero.
double robust_semivariance(const Eigen::VectorXd& r, int h) {
  std::vector<double> d;
  for (Eigen::Index i = h; i < r.size(); ++i) d.push_back(std::abs(r(i) - r(i - h)));
  const double scale = 1.4826 * median(std::move(d));
  return 0.5 * scale * scale;
}

struct VariogramFit {
  double sigma2 = 0.0, phi = 0.0, sse = INFINITY;
  double structure = 0.0;  ///< b h + c h^2 at the longest lag: the slow change the fit gave to structure
};

/// gamma(h) = s2 (1 - phi^h) + b h + c h^2 for fixed phi: linear least squares with b, c >= 0
/// (the four sign patterns, the best feasible one).
VariogramFit fit_for_phi(const Eigen::VectorXd& gamma, double phi) {
  const int n = static_cast<int>(gamma.size());
  Eigen::MatrixXd design(n, 3);
  for (int h = 1; h <= n; ++h) design.row(h - 1) << 1.0 - std::pow(phi, h), h, static_cast<double>(h) * h;
  VariogramFit best;
  for (int mask = 0; mask < 4; ++mask) {
    std::vector<int> columns{0};
    if (mask & 1) columns.push_back(1);
    if (mask & 2) columns.push_back(2);
    Eigen::MatrixXd a(n, static_cast<Eigen::Index>(columns.size()));
    for (std::size_t k = 0; k < columns.size(); ++k) a.col(static_cast<Eigen::Index>(k)) = design.col(columns[k]);
    const Eigen::VectorXd x = a.colPivHouseholderQr().solve(gamma);
    if ((x.array() < 0.0).any()) continue;
    const double sse = (a * x - gamma).squaredNorm();
    if (sse < best.sse) {
      const double h = static_cast<double>(n);
      const double b = (mask & 1) ? x(1) : 0.0, c = (mask & 2) ? x(static_cast<Eigen::Index>(columns.size()) - 1) : 0.0;
      best = {x(0), phi, sse, b * h + c * h * h};
    }
  }
  return best;
}

/// The best fit of the variogram over phi in [0, highest_phi] (steps of 0.005).
VariogramFit fit_variogram(const Eigen::VectorXd& gamma, double highest_phi) {
  VariogramFit best;
  for (int k = 0; k <= static_cast<int>(std::lround(highest_phi * 200.0)); ++k) {
    const VariogramFit f = fit_for_phi(gamma, k / 200.0);
    if (f.sse < best.sse) best = f;
  }
  return best;
}

Eigen::VectorXd semivariances(const Eigen::VectorXd& r, int lags) {
  Eigen::VectorXd gamma(lags);
  for (int h = 1; h <= lags; ++h) gamma(h - 1) = robust_semivariance(r, h);
  return gamma;
}

/// Mean over median-based lag-1 semivariance: the tails of the noise's increments.
double tail_factor(const Eigen::VectorXd& r) {
  const double robust = robust_semivariance(r, 1);
  if (!(robust > 0.0) || r.size() < 3) return 1.0;
  const double mean = 0.5 * (r.tail(r.size() - 1) - r.head(r.size() - 1)).squaredNorm() / static_cast<double>(r.size() - 1);
  return std::clamp(mean / robust, 1.0, kTailCap);
}

struct ChannelNoise {
  double sigma = 0.0, phi = 0.0, tail = 1.0;
};

/// sigma, phi and (as noise) the tail factor of one channel.
ChannelNoise channel_noise(const Eigen::VectorXd& r, bool as_noise) {
  if (r.size() < 2) return {};
  const double tail = as_noise ? tail_factor(r) : 1.0;
  const int lags = static_cast<int>(std::min<Eigen::Index>(kMaxLag, r.size() / 4));
  if (lags < 3) return {std::sqrt(robust_semivariance(r, 1)), 0.0, tail};
  VariogramFit best = fit_variogram(semivariances(r, lags), 0.95);
  const int long_lags = static_cast<int>(std::min<Eigen::Index>(kLongestLag, r.size() / 4));
  if (as_noise && best.phi >= kLongPhi && long_lags > lags) {
    // Only noise may take the long lags: a long fit that needs the structure terms (a residual
    // that follows the sweeps, whose variogram keeps growing) is structure, which the short fit
    // already leaves to b and c. Pure AR(1) noise fits sigma^2 (1 - phi^h) alone, and well.
    const int wanted = static_cast<int>(std::ceil(3.0 / (1.0 - std::min(best.phi, 0.97))));
    const Eigen::VectorXd gamma = semivariances(r, std::clamp(wanted, lags, long_lags));
    const VariogramFit longer = fit_variogram(gamma, 0.99);
    const double rms_misfit = std::sqrt(longer.sse / static_cast<double>(gamma.size()));
    if (longer.structure < kLongStructureShare * gamma(gamma.size() - 1) && rms_misfit < kLongMisfitShare * gamma.mean()) {
      best = longer;
    }
  }
  return {std::sqrt(std::max(best.sigma2, 0.0)), best.phi, tail};
}

}  // namespace

double NoiseEstimate::variance_inflation() const {
  const double p = std::clamp(phi.maxCoeff(), 0.0, 0.99);
  return (1.0 + p) / (1.0 - p);
}

NoiseEstimate estimate_noise(const Eigen::MatrixX2d& residual, bool as_noise) {
  NoiseEstimate out;
  for (int c = 0; c < 2; ++c) {
    const ChannelNoise noise = channel_noise(residual.col(c), as_noise);
    out.sigma_nm(c) = noise.sigma;
    out.phi(c) = noise.phi;
    out.tail(c) = noise.tail;
  }
  return out;
}

std::vector<std::size_t> outlier_positions(const Eigen::MatrixX2d& residual, double k) {
  const Eigen::Index n = residual.rows();
  std::vector<bool> flagged(static_cast<std::size_t>(n), false);
  if (n < 2 * kMedianHalf + 1) return {};
  for (int c = 0; c < 2; ++c) {
    Eigen::VectorXd deviation(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Index from = std::max<Eigen::Index>(0, i - kMedianHalf);
      const Eigen::Index to = std::min<Eigen::Index>(n, i + kMedianHalf + 1);
      std::vector<double> window(residual.col(c).data() + from, residual.col(c).data() + to);
      deviation(i) = residual(i, c) - median(std::move(window));
    }
    std::vector<double> magnitudes(deviation.data(), deviation.data() + n);
    for (double& m : magnitudes) m = std::abs(m);
    const double scale = 1.4826 * median(magnitudes);
    if (scale <= 0.0) continue;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (std::abs(deviation(i)) > k * scale) flagged[static_cast<std::size_t>(i)] = true;
    }
  }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < flagged.size(); ++i) if (flagged[i]) out.push_back(i);
  return out;
}

double pooled_mean_square(const Eigen::MatrixX2d& residual) {
  return residual.rows() == 0 ? 0.0 : residual.squaredNorm() / (2.0 * static_cast<double>(residual.rows()));
}

}  // namespace gc
