#include "diagnosis/slow_wander.h"

#include <algorithm>

namespace gc {
namespace {

/// Both channels' variance of the means of kWanderBlocks contiguous blocks [N²·m²].
double block_mean_variance(const Eigen::MatrixX2d& series) {
  const Eigen::Index length = series.rows() / kWanderBlocks;
  if (length < 1) return 0.0;
  Eigen::MatrixX2d means(kWanderBlocks, 2);
  for (int b = 0; b < kWanderBlocks; ++b) means.row(b) = series.middleRows(b * length, length).colwise().mean();
  return (means.rowwise() - means.colwise().mean()).squaredNorm() / (2.0 * (kWanderBlocks - 1));
}

double variance(const Eigen::MatrixX2d& series) {
  return series.rows() < 2 ? 0.0
                           : (series.rowwise() - series.colwise().mean()).squaredNorm() /
                                 (2.0 * static_cast<double>(series.rows() - 1));
}

}  // namespace

double slow_share(const Eigen::MatrixX2d& series) {
  const double v = variance(series);
  return v > 0.0 ? std::min(1.0, block_mean_variance(series) / v) : 0.0;
}

bool stands_out_of_wander(const Eigen::MatrixX2d& correction, const Eigen::MatrixX2d& left) {
  if (correction.rows() < 2 * kWanderBlocks || slow_share(correction) < 0.5) return true;
  return block_mean_variance(correction) >= 4.0 * block_mean_variance(left);
}

}  // namespace gc
