// The noise of a residual as real test-cell data has it: coloured (autocorrelated), with spikes.
//
// Sigma and the lag-1 correlation phi come from a fit to the residual's robust variogram:
//   gamma(h) = 1/2 E[(r(t+h) - r(t))^2] = sigma^2 (1 - phi^h) + b h + c h^2,   h = 1..10 samples,
// an AR(1) noise plus the slow change of whatever structure the residual still holds (b, c >= 0).
// Successive differences alone (gamma(1)) see only sigma^2 (1 - phi): 45 % of sigma^2 at phi 0.55,
// which is how an autocorrelated noise passed for an effect. Each gamma(h) is median-based
// ((1.4826 MAD)^2 / 2 of the lag-h differences), so spikes do not inflate it.
//
// Outliers: samples that stand out of the running median of their 7 neighbours in time by more than
// 7 times the robust scale of such deviations. A running median keeps steps (an effect that flips
// with the direction of travel) and follows smooth structure, so only isolated spikes qualify.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace gc {

struct NoiseEstimate {
  Eigen::Vector2d sigma_nm = Eigen::Vector2d::Zero();  ///< per channel, marginal standard deviation [N·m]
  Eigen::Vector2d phi = Eigen::Vector2d::Zero();       ///< per channel, lag-1 autocorrelation [-]
  /// Pooled sigma over both channels [N·m].
  double pooled_sigma_nm() const { return std::sqrt(sigma_nm.squaredNorm() / 2.0); }
  /// How much correlation inflates the variance of a mean over a contiguous stretch, (1 + phi) /
  /// (1 - phi), the worse channel: n samples carry n / inflation independent ones.
  double variance_inflation() const;
};

/// `residual` rows in time order (at least 12 rows for the variogram; fewer give lag-1 only).
NoiseEstimate estimate_noise(const Eigen::MatrixX2d& residual);

/// Positions (into the rows of `residual`, in time order) of samples more than `k` robust
/// deviations from the running median of their neighbours, on either channel.
std::vector<std::size_t> outlier_positions(const Eigen::MatrixX2d& residual, double k = 7.0);

/// Both channels' mean square over the rows [N·m²].
double pooled_mean_square(const Eigen::MatrixX2d& residual);

}  // namespace gc
