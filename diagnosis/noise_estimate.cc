#include "diagnosis/noise_estimate.h"

#include <algorithm>
#include <cmath>

#include "diagnosis/median.h"

namespace gc {
namespace {

constexpr int kMaxLag = 10;     ///< samples: beyond a few correlation times of most noise we meet
constexpr double kTailCap = 20.0;  ///< t(2)-like tails: beyond this the mean square says little
constexpr int kMedianHalf = 3;  ///< running median over 7 samples
constexpr std::size_t kLongestSpike = 2;  ///< samples in a spike at most, and the rows that keep spikes apart
constexpr double kNeighbourShare = 0.5;  ///< of the threshold: a neighbour this far out makes a flagged sample part of structure

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

struct ChannelNoise {
  double sigma = 0.0, phi = 0.0, tail = 1.0;
};

/// A residual taken for noise (no input shows structure in it): its marginal robust scale is the
/// noise's sigma, its lag-1 correlation 1 - gamma(1) / sigma^2, and its mean square over sigma^2
/// the tail factor. A short variogram cannot tell a correlation time of 1.5 s at 10 Hz from slow
/// structure (it gave sigma 0.7 kN·m for 2.2 kN·m of such noise); the marginal scale needs no lags.
ChannelNoise marginal_noise(const Eigen::VectorXd& r) {
  std::vector<double> values(r.data(), r.data() + r.size());
  const double centre = median(values);
  for (double& v : values) v = std::abs(v - centre);
  const double sigma = 1.4826 * median(std::move(values));
  if (!(sigma > 0.0)) return {};
  const double phi = std::clamp(1.0 - robust_semivariance(r, 1) / (sigma * sigma), 0.0, 0.99);
  const double mean_square = (r.array() - centre).square().mean();
  return {sigma, phi, std::clamp(mean_square / (sigma * sigma), 1.0, kTailCap)};
}

/// sigma and phi of one channel from its variogram (the tail factor 1), or as noise.
ChannelNoise channel_noise(const Eigen::VectorXd& r, bool as_noise) {
  if (r.size() < 2) return {};
  if (as_noise && r.size() >= 12) return marginal_noise(r);
  const int lags = static_cast<int>(std::min<Eigen::Index>(kMaxLag, r.size() / 4));
  if (lags < 3) return {std::sqrt(robust_semivariance(r, 1)), 0.0, 1.0};
  const VariogramFit best = fit_variogram(semivariances(r, lags), 0.95);
  return {std::sqrt(std::max(best.sigma2, 0.0)), best.phi, 1.0};
}

/// The flagged positions that are isolated: flagged samples within kLongestSpike rows of each other
/// form a group, and a group of at most kLongestSpike samples with no other large deviation within
/// kLongestSpike rows is a spike. Anything else is structure, kept for the physics: a lightly damped
/// resonance ringing after each torque step lost 14 rows in a row as "outliers"; one that alternates
/// in sign has every other sample flagged against the running median, and the peaks of its decaying
/// tail stand alone above the threshold with their neighbours just below it.
std::vector<std::size_t> isolated(const std::vector<bool>& flagged, const std::vector<bool>& large) {
  std::vector<std::size_t> positions, out;
  for (std::size_t i = 0; i < flagged.size(); ++i) if (flagged[i]) positions.push_back(i);
  for (std::size_t start = 0; start < positions.size();) {
    std::size_t end = start + 1;
    while (end < positions.size() && positions[end] - positions[end - 1] <= kLongestSpike) ++end;
    const std::size_t from = positions[start] >= kLongestSpike ? positions[start] - kLongestSpike : 0;
    const std::size_t to = std::min(flagged.size(), positions[end - 1] + kLongestSpike + 1);
    bool alone = end - start <= kLongestSpike;
    for (std::size_t i = from; i < to && alone; ++i) alone = flagged[i] || !large[i];
    if (alone) out.insert(out.end(), positions.begin() + static_cast<std::ptrdiff_t>(start), positions.begin() + static_cast<std::ptrdiff_t>(end));
    start = end;
  }
  return out;
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

std::vector<std::size_t> outlier_positions(const Eigen::MatrixX2d& residual, double k, const Eigen::Array2d& least_scale) {
  const Eigen::Index n = residual.rows();
  if (n < 2 * kMedianHalf + 1) return {};
  std::vector<std::size_t> out;
  for (int c = 0; c < 2; ++c) {  // isolation is judged on the channel that spiked
    std::vector<bool> flagged(static_cast<std::size_t>(n), false), large(static_cast<std::size_t>(n), false);
    Eigen::VectorXd deviation(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Index from = std::max<Eigen::Index>(0, i - kMedianHalf);
      const Eigen::Index to = std::min<Eigen::Index>(n, i + kMedianHalf + 1);
      std::vector<double> window(residual.col(c).data() + from, residual.col(c).data() + to);
      deviation(i) = residual(i, c) - median(std::move(window));
    }
    std::vector<double> magnitudes(deviation.data(), deviation.data() + n);
    for (double& m : magnitudes) m = std::abs(m);
    const double scale = std::max(1.4826 * median(magnitudes), least_scale(c));
    if (scale <= 0.0) continue;
    for (Eigen::Index i = 0; i < n; ++i) {
      flagged[static_cast<std::size_t>(i)] = std::abs(deviation(i)) > k * scale;
      large[static_cast<std::size_t>(i)] = std::abs(deviation(i)) > kNeighbourShare * k * scale;
    }
    const std::vector<std::size_t> spikes = isolated(flagged, large);
    out.insert(out.end(), spikes.begin(), spikes.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double long_run_inflation(const Eigen::VectorXd& x) {
  constexpr Eigen::Index kBlocks = 50;
  const Eigen::Index length = x.size() / kBlocks;
  const double variance = x.squaredNorm() / static_cast<double>(x.size());
  if (length < 2 || !(variance > 0.0)) return 1.0;
  double means = 0.0;
  for (Eigen::Index b = 0; b < kBlocks; ++b) means += std::pow(x.segment(b * length, length).mean(), 2);
  return std::max(1.0, static_cast<double>(length) * means / static_cast<double>(kBlocks) / variance);
}

double level_standard_errors(const Eigen::MatrixX2d& residual) {
  const Eigen::Index n = residual.rows();
  if (n < 100) return 0.0;
  double most = 0.0;
  for (int c = 0; c < 2; ++c) {
    const double mean = residual.col(c).mean();
    const Eigen::VectorXd about = residual.col(c).array() - mean;
    const double variance = about.squaredNorm() / static_cast<double>(n);
    const double error = std::sqrt(variance * long_run_inflation(about) / static_cast<double>(n));
    if (error > 0.0) most = std::max(most, std::abs(mean) / error);
  }
  return most;
}

double pooled_mean_square(const Eigen::MatrixX2d& residual) {
  return residual.rows() == 0 ? 0.0 : residual.squaredNorm() / (2.0 * static_cast<double>(residual.rows()));
}

}  // namespace gc
