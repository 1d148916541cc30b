#include "diagnosis/whitening_filter.h"

#include <algorithm>
#include <cmath>

namespace gc {
namespace {

/// Levinson-Durbin on autocovariances `r` (lags 0..most) of a series of n rows: the order of
/// least AIC, n log(sigma_k^2) + 2k, and its coefficients.
Eigen::VectorXd levinson(const Eigen::VectorXd& r, Eigen::Index n) {
  const int most = static_cast<int>(r.size()) - 1;
  if (most < 1 || !(r(0) > 0.0) || !r.allFinite()) return {};
  Eigen::VectorXd a = Eigen::VectorXd::Zero(most), previous(most), best;
  double error = r(0);
  double best_aic = static_cast<double>(n) * std::log(error);
  for (int k = 1; k <= most; ++k) {
    double acc = r(k);
    for (int j = 1; j < k; ++j) acc -= a(j - 1) * r(k - j);
    const double reflection = acc / error;
    if (!(std::abs(reflection) < 1.0)) break;
    previous = a;
    a(k - 1) = reflection;
    for (int j = 1; j < k; ++j) a(j - 1) = previous(j - 1) - reflection * previous(k - j - 1);
    error *= 1.0 - reflection * reflection;
    if (!(error > 0.0)) break;
    const double aic = static_cast<double>(n) * std::log(error) + 2.0 * k;
    if (aic < best_aic) {
      best_aic = aic;
      best = a.head(k);
    }
  }
  return best;
}

/// The whitening of a noise whose adjacent rows are correlated beyond kSlow (`r`: autocovariances,
/// lags 0..): (1 - L)(1 - sum_k b_k L^k), with b the autoregression of the differences (whose
/// autocovariances are 2 r_k - r_{k-1} - r_{k+1}); none for a faster noise. Differenced, since a
/// Yule-Walker fit of a walk stops short of its unit root (0.99 on 600 rows) and what it leaves of
/// the walk is slow enough for slow terms to explain as the spurious regression does (a level and
/// a staircase on random walks: 9 claims of 300). Only slow noise, since on a slow AR(1) under
/// white noise (phi 0.98, lag-1 correlation 0.5) a whitened three quarters of a slow cycle was found
/// in 59-66 of 100 draws against 92 on the rows as they are
/// (Surrogates.FindsASlowTermWhoseProgrammeEndsElsewhere). At 0.7 the zoo's power was the same
/// over two fresh seeds (317 of 380: a twice per revolution and a misalignment offset under brown
/// and sample-and-hold noise gained, a speed drag and a friction lost).
Eigen::VectorXd autoregression(const Eigen::VectorXd& r, Eigen::Index rows, Eigen::Index most) {
  constexpr double kSlow = 0.9;
  if (most < 2 || r.size() < 3 || !(r(0) > 0.0) || !(r(1) > kSlow * r(0))) return {};
  const Eigen::Index lags = std::min<Eigen::Index>(r.size() - 2, most - 1);
  Eigen::VectorXd differences(lags + 1);
  for (Eigen::Index k = 0; k <= lags; ++k) differences(k) = 2.0 * r(k) - r(k + 1) - r(k == 0 ? 1 : k - 1);
  const Eigen::VectorXd b = levinson(differences, rows);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(b.size() + 1);
  a(0) = 1.0;
  for (Eigen::Index k = 0; k < b.size(); ++k) {
    a(k) += b(k);
    a(k + 1) -= b(k);
  }
  return a;
}

}  // namespace

WhiteningFilter WhiteningFilter::of_autocovariances(const std::array<Eigen::VectorXd, 2>& covariances, Eigen::Index rows,
                                                    int most_order) {
  WhiteningFilter out;
  const Eigen::Index most = std::min<Eigen::Index>(most_order, rows / 20);
  for (int c = 0; c < 2; ++c) out.a[static_cast<std::size_t>(c)] = autoregression(covariances[static_cast<std::size_t>(c)], rows, most);
  return out;
}

Eigen::Index WhiteningFilter::order() const { return std::max(a[0].size(), a[1].size()); }

Eigen::MatrixXd WhiteningFilter::applied(const Eigen::MatrixXd& stacked) const {
  const Eigen::Index n = stacked.rows() / 2, p = order(), kept = n - p;
  if (p == 0) return stacked;
  Eigen::MatrixXd out(2 * kept, stacked.cols());
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd& coefficients = a[static_cast<std::size_t>(c)];
    auto filtered = out.middleRows(c * kept, kept);
    filtered = stacked.middleRows(c * n + p, kept);
    for (Eigen::Index k = 1; k <= coefficients.size(); ++k) {
      filtered -= coefficients(k - 1) * stacked.middleRows(c * n + p - k, kept);
    }
  }
  return out;
}

}  // namespace gc
