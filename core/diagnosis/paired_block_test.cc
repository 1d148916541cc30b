#include "core/diagnosis/paired_block_test.h"

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

}  // namespace

PairedBlockTest paired_block_test(const Eigen::MatrixX2d& a, const Eigen::MatrixX2d& b,
                                  const std::vector<int>& block_of, int blocks) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(blocks), count = Eigen::VectorXd::Zero(blocks);
  const Eigen::VectorXd difference = 0.5 * (a.rowwise().squaredNorm() - b.rowwise().squaredNorm());
  for (Eigen::Index i = 0; i < difference.size(); ++i) {
    sum(block_of[static_cast<std::size_t>(i)]) += difference(i);
    count(block_of[static_cast<std::size_t>(i)]) += 1.0;
  }
  PairedBlockTest out;
  std::vector<double> means;
  for (int k = 0; k < blocks; ++k) if (count(k) > 0) means.push_back(sum(k) / count(k));
  out.blocks = static_cast<int>(means.size());
  if (means.size() < 2) return out;
  winsorize(means);
  const Eigen::Map<const Eigen::VectorXd> m(means.data(), static_cast<Eigen::Index>(means.size()));
  out.mean_difference = m.mean();
  const double sd = std::sqrt((m.array() - out.mean_difference).square().sum() / (m.size() - 1.0));
  out.t = sd > 0.0 ? out.mean_difference / (sd / std::sqrt(static_cast<double>(m.size()))) : 0.0;
  return out;
}

}  // namespace gc
