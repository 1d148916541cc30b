// The whitening filter of the surrogate test's statistic (diagnosis/whitening_filter.h).
#include "diagnosis/whitening_filter.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace gc {
namespace {

/// Autocovariances at lags 0..lags of `x` (its mean removed).
Eigen::VectorXd covariances(const Eigen::VectorXd& x, int lags) {
  const Eigen::ArrayXd c = x.array() - x.mean();
  Eigen::VectorXd r(lags + 1);
  for (int k = 0; k <= lags; ++k) r(k) = (c.head(c.size() - k) * c.tail(c.size() - k)).sum() / static_cast<double>(c.size());
  return r;
}

// A random walk is differenced: its filter's coefficients sum to 1 (a unit root), and what it
// leaves of a walk is the walk's steps (their variance, no lag-1 correlation). White noise, and an
// AR(1) whose adjacent rows are correlated 0.5, are left as they are.
TEST(WhiteningFilter, DifferencesAWalkAndLeavesAFasterNoiseAsItIs) {
  std::mt19937_64 random(20261202);
  std::normal_distribution<double> normal;
  const Eigen::Index n = 5000;
  Eigen::MatrixX2d walk(n, 2), fast(n, 2);
  Eigen::Vector2d at = Eigen::Vector2d::Zero(), ar = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    at += Eigen::Vector2d(normal(random), normal(random));
    ar = 0.5 * ar + Eigen::Vector2d(normal(random), normal(random));
    walk.row(i) = at.transpose();
    fast(i, 0) = normal(random);
    fast(i, 1) = ar(1);
  }
  const auto filter_of = [](const Eigen::MatrixX2d& x) {
    return WhiteningFilter::of_autocovariances({covariances(x.col(0), 8), covariances(x.col(1), 8)}, x.rows());
  };
  const WhiteningFilter walks = filter_of(walk);
  ASSERT_GE(walks.order(), 1);
  for (int c = 0; c < 2; ++c) EXPECT_NEAR(walks.a[static_cast<std::size_t>(c)].sum(), 1.0, 1e-12) << "channel " << c;
  Eigen::VectorXd stacked(2 * n);
  stacked << walk.col(0), walk.col(1);
  const Eigen::VectorXd steps = walks.applied(stacked);
  ASSERT_EQ(steps.size(), 2 * (n - walks.order()));
  const Eigen::VectorXd first = steps.head(n - walks.order());
  const Eigen::VectorXd r = covariances(first, 1);
  EXPECT_NEAR(r(0), 1.0, 0.1);           // the steps' variance
  EXPECT_NEAR(r(1) / r(0), 0.0, 0.05);   // uncorrelated
  EXPECT_TRUE(filter_of(fast).identity());
}

// Too few rows for a coefficient: none, whatever the correlation.
TEST(WhiteningFilter, NoneOnTooFewRows) {
  Eigen::VectorXd r(9);
  for (int k = 0; k <= 8; ++k) r(k) = std::pow(0.99, k);
  EXPECT_TRUE(WhiteningFilter::of_autocovariances({r, r}, 39).identity());
  EXPECT_FALSE(WhiteningFilter::of_autocovariances({r, r}, 400).identity());
}

}  // namespace
}  // namespace gc
