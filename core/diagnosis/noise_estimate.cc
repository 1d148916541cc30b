#include "core/diagnosis/noise_estimate.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gc {
namespace {

double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

Eigen::Vector2d successive_difference_noise(const Eigen::MatrixX2d& residual) {
  Eigen::Vector2d sigma = Eigen::Vector2d::Zero();
  if (residual.rows() < 2) return sigma;
  for (int c = 0; c < 2; ++c) {
    std::vector<double> differences(static_cast<std::size_t>(residual.rows() - 1));
    for (Eigen::Index i = 1; i < residual.rows(); ++i) {
      differences[static_cast<std::size_t>(i - 1)] = std::abs(residual(i, c) - residual(i - 1, c));
    }
    sigma(c) = 1.4826 * median(std::move(differences)) / std::sqrt(2.0);
  }
  return sigma;
}

double pooled_mean_square(const Eigen::MatrixX2d& residual) {
  return residual.rows() == 0 ? 0.0 : residual.squaredNorm() / (2.0 * static_cast<double>(residual.rows()));
}

}  // namespace gc
