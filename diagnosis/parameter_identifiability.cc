#include "diagnosis/parameter_identifiability.h"

#include <cmath>

namespace gc {
namespace {

/// Share of column i not explained by the other free columns: 1 - R^2 of its regression on them.
double unexplained_share(const Eigen::MatrixXd& jacobian, const std::vector<bool>& free, int i) {
  std::vector<int> others;
  for (int k = 0; k < static_cast<int>(free.size()); ++k) if (free[k] && k != i) others.push_back(k);
  const double norm2 = jacobian.col(i).squaredNorm();
  if (others.empty() || norm2 == 0.0) return 1.0;
  Eigen::MatrixXd a(jacobian.rows(), static_cast<Eigen::Index>(others.size()));
  for (std::size_t k = 0; k < others.size(); ++k) a.col(static_cast<Eigen::Index>(k)) = jacobian.col(others[k]);
  const Eigen::VectorXd fit = a * a.colPivHouseholderQr().solve(jacobian.col(i));
  return (jacobian.col(i) - fit).squaredNorm() / norm2;
}

int most_correlated(const Eigen::MatrixXd& jacobian, const std::vector<bool>& free, int i, double& r) {
  int partner = -1;
  r = 0.0;
  for (int k = 0; k < static_cast<int>(free.size()); ++k) {
    if (!free[k] || k == i) continue;
    const double denominator = jacobian.col(i).norm() * jacobian.col(k).norm();
    const double c = denominator > 0.0 ? std::abs(jacobian.col(i).dot(jacobian.col(k))) / denominator : 0.0;
    if (c >= r) { r = c; partner = k; }
  }
  return partner;
}

}  // namespace

std::optional<Unidentifiable> find_unidentifiable(const Eigen::MatrixXd& jacobian,
                                                  const std::vector<bool>& free) {
  double largest = 0.0;
  for (int k = 0; k < static_cast<int>(free.size()); ++k) if (free[k]) largest = std::max(largest, jacobian.col(k).norm());
  std::optional<Unidentifiable> worst;
  // The last flagged column: effects list their magnitudes first and the modifiers after.
  for (int i = 0; i < static_cast<int>(free.size()); ++i) {
    if (!free[i]) continue;
    if (largest == 0.0 || jacobian.col(i).norm() <= 1e-9 * largest) {
      worst = Unidentifiable{i, -1, 0.0};  // no influence at all
      continue;
    }
    if (unexplained_share(jacobian, free, i) <= 1e-4) {
      Unidentifiable u{i, -1, 0.0};
      u.partner = most_correlated(jacobian, free, i, u.correlation);
      worst = u;
    }
  }
  return worst;
}

}  // namespace gc
