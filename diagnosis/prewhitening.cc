#include "diagnosis/prewhitening.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/input_noise.h"

namespace gc {
namespace {

/// a_1..a_p of the order the information criterion prefers: the lags' QR (unpivoted, so that its
/// first p columns are the model of order p) gives every order's residual sum of squares at once.
Eigen::VectorXd autoregression(const Eigen::VectorXd& series) {
  const Eigen::Index n = series.size();
  const Eigen::Index most = std::min(Prewhitening::kMostOrder, n / 50);
  if (most < 1) return {};
  const Eigen::VectorXd x = series.array() - series.mean();
  const Eigen::Index m = n - most;  // one sample for every order
  Eigen::MatrixXd lags(m, most);
  for (Eigen::Index i = 0; i < most; ++i) lags.col(i) = x.segment(most - 1 - i, m);
  const Eigen::VectorXd y = x.tail(m);
  if (!lags.allFinite() || !y.allFinite()) return {};
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(lags);
  const Eigen::VectorXd qty = qr.householderQ().transpose() * y;
  double rss = y.squaredNorm();
  if (!(rss > 0.0)) return {};
  Eigen::Index order = 0;
  double best = static_cast<double>(m) * std::log(rss / static_cast<double>(m));
  const double penalty = std::log(static_cast<double>(m));
  for (Eigen::Index p = 1; p <= most; ++p) {
    rss -= qty(p - 1) * qty(p - 1);
    if (!(rss > 0.0)) break;
    const double bic = static_cast<double>(m) * std::log(rss / static_cast<double>(m)) + static_cast<double>(p) * penalty;
    if (bic < best) {
      best = bic;
      order = p;
    }
  }
  if (order == 0) return {};
  const Eigen::VectorXd a = qr.matrixQR().topLeftCorner(order, order).triangularView<Eigen::Upper>().solve(qty.head(order));
  return a.allFinite() ? a : Eigen::VectorXd{};
}

}  // namespace

Prewhitening Prewhitening::fitted(const Eigen::MatrixX2d& x) {
  Prewhitening out;
  for (int c = 0; c < 2; ++c) out.coefficients[static_cast<std::size_t>(c)] = autoregression(x.col(c));
  return out;
}

Eigen::MatrixXd Prewhitening::applied(const Eigen::MatrixXd& stacked) const {
  const Eigen::Index n = stacked.rows() / 2;
  Eigen::MatrixXd out(stacked.rows(), stacked.cols());
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd& a = coefficients[static_cast<std::size_t>(c)];
    const Eigen::Index p = std::min(a.size(), n);
    const auto in = stacked.middleRows(c * n, n);
    auto filtered = out.middleRows(c * n, n);
    filtered.topRows(p).setZero();
    filtered.bottomRows(n - p) = in.bottomRows(n - p);
    for (Eigen::Index i = 1; i <= p; ++i) filtered.bottomRows(n - p) -= a(i - 1) * in.middleRows(p - i, n - p);
  }
  return out;
}

bool exposes_input_noise(const Eigen::MatrixX2d& residual, const Eigen::Array2d& input_noise_nm) {
  const Eigen::Index n = residual.rows();
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd r = residual.col(c);
    const double sigma_r = input_noise_sigma(std::span<const double>(r.data(), static_cast<std::size_t>(n)));
    if (!(input_noise_nm(c) * input_noise_nm(c) * static_cast<double>(n) <= sigma_r * sigma_r)) return true;
  }
  return false;
}

}  // namespace gc
