#include "core/diagnosis/paired_block_test.h"

#include <cmath>

namespace gc {

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
  const Eigen::Map<const Eigen::VectorXd> m(means.data(), static_cast<Eigen::Index>(means.size()));
  out.mean_difference = m.mean();
  const double sd = std::sqrt((m.array() - out.mean_difference).square().sum() / (m.size() - 1.0));
  out.t = sd > 0.0 ? out.mean_difference / (sd / std::sqrt(static_cast<double>(m.size()))) : 0.0;
  return out;
}

}  // namespace gc
