// The two moment channels (M_sy', M_sz') of n rows as one vector of 2n, and back: how least squares
// over both channels at once sees a residual (rows k for M_sy', n + k for M_sz'), as the formula
// search and the surrogate test stack their designs.
#pragma once

#include <Eigen/Dense>

namespace gc {

/// Rows k of `channels` at k (M_sy') and n + k (M_sz').
inline Eigen::VectorXd stacked(const Eigen::MatrixX2d& channels) {
  Eigen::VectorXd y(2 * channels.rows());
  y << channels.col(0), channels.col(1);
  return y;
}

/// The inverse of stacked: `y` (2n) as n rows of two channels.
inline Eigen::MatrixX2d unstacked(const Eigen::VectorXd& y) {
  const Eigen::Index n = y.size() / 2;
  Eigen::MatrixX2d channels(n, 2);
  channels.col(0) = y.head(n);
  channels.col(1) = y.tail(n);
  return channels;
}

}  // namespace gc
