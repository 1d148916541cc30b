// The measurement noise of a recording, estimated from successive differences of the residual
// in time order: the systematic part of a residual changes little from one sample to the next,
// so r_{i+1} - r_i is noise with variance 2 sigma^2. The median absolute difference (times
// 1.4826 / sqrt 2) keeps the estimate robust to the jumps between load steps.
#pragma once

#include <Eigen/Dense>

namespace gc {

/// Per channel, sigma [N·m] of white noise on a residual whose rows are in time order;
/// zeros for fewer than two rows.
Eigen::Vector2d successive_difference_noise(const Eigen::MatrixX2d& residual);

/// Mean over rows and both channels of r^2 / 2 per channel: the pooled mean squared error.
double pooled_mean_square(const Eigen::MatrixX2d& residual);

}  // namespace gc
