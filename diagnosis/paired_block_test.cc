#include "diagnosis/paired_block_test.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gc {
namespace {

/// The share of blocks at either end pulled in to the next value: one transient (a torque step of
/// 1.6 MN·m in one block) must not make a gain found in every other block insignificant by the
/// variance it alone adds. Both ends alike, so a difference of no sign stays one of no sign.
constexpr double kWinsorShare = 0.01;

void winsorize(std::vector<double>& values) {
  const auto k = static_cast<std::size_t>(std::ceil(kWinsorShare * static_cast<double>(values.size())));
  if (values.size() < 2 * k + 2) return;
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const double low = sorted[k], high = sorted[sorted.size() - 1 - k];
  for (double& v : values) v = std::clamp(v, low, high);
}

double variance(const Eigen::VectorXd& x) {
  return x.size() < 2 ? 0.0 : (x.array() - x.mean()).square().sum() / (static_cast<double>(x.size()) - 1.0);
}

/// Means of `length` consecutive values (the last partial batch left out).
Eigen::VectorXd batch_means(const Eigen::VectorXd& series, Eigen::Index length) {
  const Eigen::Index batches = series.size() / length;
  Eigen::VectorXd means(batches);
  for (Eigen::Index j = 0; j < batches; ++j) means(j) = series.segment(j * length, length).mean();
  return means;
}

/// Per block (present ones, in order), the mean of each column of `x`.
Eigen::MatrixXd block_means(const Eigen::MatrixXd& x, const std::vector<int>& block_of, int blocks) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(blocks, x.cols());
  Eigen::VectorXd count = Eigen::VectorXd::Zero(blocks);
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    sum.row(block_of[static_cast<std::size_t>(i)]) += x.row(i);
    count(block_of[static_cast<std::size_t>(i)]) += 1.0;
  }
  Eigen::MatrixXd out(static_cast<Eigen::Index>((count.array() > 0.0).count()), x.cols());
  for (Eigen::Index k = 0, j = 0; k < blocks; ++k) if (count(k) > 0) out.row(j++) = sum.row(k) / count(k);
  return out;
}

}  // namespace

double long_run_ratio(const Eigen::VectorXd& series, int least_batches) {
  const double v = variance(series);
  if (!(v > 0.0)) return 1.0;
  double ratio = 1.0;
  const Eigen::Index least = std::max(2, least_batches);
  for (Eigen::Index length = 2; series.size() / length >= least; length *= 2) {
    ratio = std::max(ratio, variance(batch_means(series, length)) * static_cast<double>(length) / v);
  }
  return ratio;
}

PairedBlockTest paired_block_test(const Eigen::MatrixX2d& a, const Eigen::MatrixX2d& b,
                                  const std::vector<int>& block_of, int blocks, bool long_run) {
  const Eigen::VectorXd difference = 0.5 * (a.rowwise().squaredNorm() - b.rowwise().squaredNorm());
  const Eigen::MatrixXd means_matrix = block_means(difference, block_of, blocks);
  PairedBlockTest out;
  std::vector<double> means(means_matrix.data(), means_matrix.data() + means_matrix.rows());
  out.blocks = static_cast<int>(means.size());
  if (means.size() < 2) return out;
  winsorize(means);
  const Eigen::Map<const Eigen::VectorXd> m(means.data(), static_cast<Eigen::Index>(means.size()));
  out.mean_difference = m.mean();
  // The noise's correlation between blocks, on the better model's residual (b when t > 0).
  if (long_run) {
    const Eigen::MatrixXd noise = block_means(out.mean_difference >= 0.0 ? b : a, block_of, blocks);
    for (Eigen::Index c = 0; c < noise.cols(); ++c) out.inflation = std::max(out.inflation, long_run_ratio(noise.col(c)));
  }
  const double sd = std::sqrt(variance(m));
  out.t = sd > 0.0 ? out.mean_difference / (sd * std::sqrt(out.inflation / static_cast<double>(m.size()))) : 0.0;
  return out;
}

}  // namespace gc
