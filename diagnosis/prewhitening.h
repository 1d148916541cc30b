// A causal prewhitening filter for a residual's noise: the autoregression that predicts each row of a
// channel from the rows before it, e_t = x_t - sum_{i=1..p} a_i x_{t-i}, fitted by least squares,
// its order p chosen by the Bayesian information criterion (Schwarz, 1978). Applied alike to a
// residual, to its surrogates and to a candidate's design, it turns least squares into generalised
// least squares for that noise (Cochrane and Orcutt, 1949): under a random walk a torque step is a
// jump of several kN·m against increments of tens of N·m a row, where unfiltered it is one more
// slow wander among many.
#pragma once

#include <array>

#include <Eigen/Dense>

namespace gc {

struct Prewhitening {
  /// Per channel, a_1..a_p (empty: the channel is left as it is).
  std::array<Eigen::VectorXd, 2> coefficients;

  /// The largest order tried, and never more than a fiftieth of the rows.
  static constexpr Eigen::Index kMostOrder = 20;

  /// Fitted to each channel of `x` (rows in time order), its mean taken out.
  static Prewhitening fitted(const Eigen::MatrixX2d& x);

  /// The input sensors put white noise in the model's prediction that the filter would expose
  /// (exposes_input_noise below): a share of the inputs on filtered rows is then not the noise's
  /// alone.
  bool exposes_input_noise = false;

  /// Both channels left as they are.
  bool identity() const { return coefficients[0].size() == 0 && coefficients[1].size() == 0; }

  /// The filter applied to each column of `stacked` (2n rows: n for M_sy', then n for M_sz'): the
  /// first p rows of each channel, which have no p rows before them, are 0.
  Eigen::MatrixXd applied(const Eigen::MatrixXd& stacked) const;
};

/// Whether the input sensors put white noise in the prediction that a filter of `residual` would
/// expose (Prewhitening::exposes_input_noise): `input_noise_nm`, per channel, is the white noise
/// the input sensors put in the model's prediction (input_noise_in_prediction.h). A design made
/// from the same measured inputs holds that noise too (errors in the variables). Under a random
/// walk the walk drowns the correlation; filtered, the walk's increments are small and the inputs'
/// noise is a share of about sigma_p^2 / sigma_r^2 of what is left (sigma_r the residual's white
/// noise, from its second differences: core/input_noise.h), which a design of the inputs explains.
/// A share that large stands out of noise's own on n rows unless it is under 1 / n, so the filter
/// is clean only where it is, on both channels. Proximity probes' noise of 3.5e-5 rad beside brown
/// noise gave a formula of slow terms and T zeta, 30 % held out, p = 0 filtered (the CI sample's
/// draw 32, zoo seed 20250601).
bool exposes_input_noise(const Eigen::MatrixX2d& residual, const Eigen::Array2d& input_noise_nm);

}  // namespace gc
