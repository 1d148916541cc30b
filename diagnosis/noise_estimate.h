// The noise of a residual as real test-cell data has it: coloured (autocorrelated), with spikes.
//
// Sigma and the lag-1 correlation phi come from a fit to the residual's robust variogram:
//   gamma(h) = 1/2 E[(r(t+h) - r(t))^2] = sigma^2 (1 - phi^h) + b h + c h^2,   h = 1..10 samples,
// an AR(1) noise plus the slow change of whatever structure the residual still holds (b, c >= 0).
// Successive differences alone (gamma(1)) see only sigma^2 (1 - phi): 45 % of sigma^2 at phi 0.55,
// which is how an autocorrelated noise passed for an effect. Each gamma(h) is median-based
// ((1.4826 MAD)^2 / 2 of the lag-h differences), so spikes do not inflate it.
//
// Heavy tails (where the residual is taken for noise): a robust sigma is the right scale for tests
// of structure, but the mean square of a Student-t noise is several times sigma^2. The ratio of the mean to the median-based lag-1
// semivariance says how much (NoiseEstimate::tail), so that a residual RMS above sigma is not taken
// for physics. Long correlation: when the fit puts phi at 0.8 or more, the variogram is refitted
// on lags up to three correlation times (at most 100), phi up to 0.99: at 10 Hz with a correlation
// time of 2 s, ten lags see only 40 % of sigma^2.
//
// Outliers: samples that stand out of the running median of their 7 neighbours in time by more than
// 7 times the robust scale of such deviations. A running median keeps steps (an effect that flips
// with the direction of travel) and follows smooth structure; and only isolated spikes qualify:
// flagged samples within 2 rows of each other form a group, and a group of more than 2, or one with
// a deviation of half the threshold within 2 rows, is structure (a resonance ringing after a torque
// step), never outliers.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace gc {

struct NoiseEstimate {
  Eigen::Vector2d sigma_nm = Eigen::Vector2d::Zero();  ///< per channel, marginal standard deviation [N·m]
  Eigen::Vector2d phi = Eigen::Vector2d::Zero();       ///< per channel, lag-1 autocorrelation [-]
  /// Per channel, the noise's mean square over sigma^2 (>= 1): how much heavier its tails are than
  /// a Gaussian's of the same robust scale; 1 for Gaussian noise, about 2 for Student-t with 3
  /// degrees of freedom. Measured only where the residual is taken for noise.
  Eigen::Vector2d tail = Eigen::Vector2d::Ones();
  /// Pooled sigma over both channels [N·m] (the robust scale).
  double pooled_sigma_nm() const { return std::sqrt(sigma_nm.squaredNorm() / 2.0); }
  /// The noise's pooled mean square [N·m²], tails included: what a residual of pure noise has.
  double mean_square() const {
    return (sigma_nm.array().square() * tail.array()).sum() / 2.0;
  }
  /// How much correlation inflates the variance of a mean over a contiguous stretch, (1 + phi) /
  /// (1 - phi), the worse channel: n samples carry n / inflation independent ones.
  double variance_inflation() const;
};

/// `residual` rows in time order (at least 12 rows for the variogram; fewer give lag-1 only).
/// `as_noise`: the residual shows no structure against any input, so what it holds is taken for
/// noise, and its marginal scale, correlation and tails are the noise's. Otherwise (the variogram)
/// slow structure would pass for noise (a residual that follows the sweeps has the variogram of an
/// AR(1) of phi 0.98), and its jumps (the sawtooth of eqs 42-43) for heavy tails.
NoiseEstimate estimate_noise(const Eigen::MatrixX2d& residual, bool as_noise = false);

/// Positions (into the rows of `residual`, in time order) of samples more than `k` robust
/// deviations from the running median of their neighbours, on either channel, that are isolated: at most 2 flagged within 2 rows of each other, and no
/// deviation of half the threshold within 2 rows of them. `least_scale` per channel [N·m]: the
/// robust deviation is never taken below it. A channel rounded to an ADC step q has q / sqrt(12)
/// of rounding noise that a median of deviations does not see: where most neighbours are equal,
/// the median deviation is the model's slow change, and every step of one q stood 7 "deviations"
/// out (652 of 3,265 rows of a 5.2 kN·m step in 2.3 kN·m of noise were excluded as spikes).
std::vector<std::size_t> outlier_positions(const Eigen::MatrixX2d& residual, double k = 7.0,
                                           const Eigen::Array2d& least_scale = Eigen::Array2d::Zero());

/// Both channels' mean square over the rows [N·m²].
double pooled_mean_square(const Eigen::MatrixX2d& residual);

/// How much the correlation of `x` (rows in time order, centred) inflates the variance of a mean
/// over a contiguous stretch: the variance of the means of 50 blocks, times the block length, over
/// the variance of the samples (a block-means estimate of the long-run variance, which sees a
/// correlation of any length shorter than a block). At least 1; 1 for fewer than 100 rows.
double long_run_inflation(const Eigen::VectorXd& x);

/// How far a channel's level stands from zero: |mean| over its long-run standard error (the
/// variance about the mean, times long_run_inflation, over the rows), the larger of the two
/// channels; 0 for fewer than 100 rows. A mean square sees an offset only beside the noise's whole
/// variance, heavy tails and all: beside an offset of 1.5 times a resonant, heavy-tailed noise the
/// residual's mean square was 0.87 times the noise's estimate (2.24 times was needed), and its
/// level 90 long-run errors from zero. Not surrogate_test.h's level_p_value, which asks whether
/// a formula's level stands out of the wander of 21 block means, a claim's bar: this asks only
/// whether there is anything to search, and every claim still meets the claim rule.
double level_standard_errors(const Eigen::MatrixX2d& residual);

}  // namespace gc
