// An autoregressive whitening filter of each moment channel, for the surrogate test's statistic
// (surrogate_test.h): the share a design explains is measured on the residual, the design and every
// surrogate after one and the same filter, e_t = x_t - sum_k a_k x_{t-k}, fitted to the noise the
// null is drawn from. On a walk (brown noise: adjacent rows correlated beyond 0.9) the share of the
// raw rows is mostly the walk's slow power, which a few slow terms of a formula's catalogue explain
// in any surrogate walk as well as in the residual: a forward order of 45 % of the held-out error
// under brown noise had a surrogate p of 1 (zoo power seed 20261308, draw 0). Whitened, the walk is
// its steps and the order stands out of them: least squares after the filter is generalised least
// squares. Faster noise is left as it is: a few autoregressive lags misjudge the low-frequency
// level a slow term stands on, and cost it power (whitening_filter.cc). The surrogates carry the
// null's spectrum and the statistic is the same function of the residual and of each, so the test
// keeps its level whatever the filter.
#pragma once

#include <array>

#include <Eigen/Dense>

namespace gc {

/// e_t = x_t - sum_{k=1..p} a_k x_{t-k} per channel; the first p rows of each channel are dropped.
struct WhiteningFilter {
  std::array<Eigen::VectorXd, 2> a;  ///< per channel, the p_c autoregressive coefficients (empty: none)

  /// The filter of a noise from each channel's autocovariances at lags 0.. (`covariances`, any
  /// common scale) of a series of `rows`: where adjacent rows are correlated beyond 0.9, the
  /// differences' Yule-Walker autoregression (Levinson-Durbin, stable) of the order up to
  /// `most_order` with the least Akaike information, after the difference; else none. Fewer than
  /// 20 rows a coefficient: none.
  static WhiteningFilter of_autocovariances(const std::array<Eigen::VectorXd, 2>& covariances, Eigen::Index rows,
                                            int most_order = 8);

  /// The rows dropped from each channel: the larger order.
  Eigen::Index order() const;
  bool identity() const { return order() == 0; }

  /// `stacked` (2n rows, channels stacked as stacked_channels.h has them; any number of columns)
  /// filtered: 2 (n - order()) rows, each channel's first order() rows dropped.
  Eigen::MatrixXd applied(const Eigen::MatrixXd& stacked) const;
};

}  // namespace gc
