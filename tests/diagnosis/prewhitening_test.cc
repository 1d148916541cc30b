// The prewhitening filter (diagnosis/prewhitening.h): the autoregression it fits, the order it
// chooses, and what it leaves of a random walk.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "diagnosis/prewhitening.h"

namespace gc {
namespace {

/// n rows of an AR(1) of `phi` with unit innovations on both channels, started in its stationary
/// state (phi < 1) or at zero (a walk, phi 1).
Eigen::MatrixX2d autoregressive(std::mt19937_64& random, double phi, Eigen::Index n) {
  std::normal_distribution<double> white;
  Eigen::MatrixX2d out(n, 2);
  for (int c = 0; c < 2; ++c) {
    double x = phi < 1.0 ? white(random) / std::sqrt(1.0 - phi * phi) : 0.0;
    for (Eigen::Index i = 0; i < n; ++i) out(i, c) = x = phi * x + white(random);
  }
  return out;
}

// An AR(1) of 0.8 over 1,500 rows: the first coefficient is 0.8 within 0.05 and any others are
// small, on 20 fresh draws.
TEST(Prewhitening, FindsAnAutoregressionsCoefficient) {
  std::mt19937_64 random(20261317);
  for (int d = 0; d < 20; ++d) {
    const Prewhitening filter = Prewhitening::fitted(autoregressive(random, 0.8, 1500));
    for (const Eigen::VectorXd& a : filter.coefficients) {
      ASSERT_GE(a.size(), 1) << "draw " << d;
      EXPECT_NEAR(a(0), 0.8, 0.05) << "draw " << d;
      for (Eigen::Index i = 1; i < a.size(); ++i) EXPECT_LT(std::abs(a(i)), 0.15) << "draw " << d << ", lag " << i + 1;
    }
  }
}

// White noise is left as it is: the information criterion prefers no lag in at least 40 of 50
// draws' channels in each (its penalty, log 1480 = 7.3 a lag, is passed by chance about once in 200
// a lag).
TEST(Prewhitening, LeavesWhiteNoiseAsItIs) {
  std::mt19937_64 random(20261318);
  int left = 0;
  for (int d = 0; d < 50; ++d) {
    const Prewhitening filter = Prewhitening::fitted(autoregressive(random, 0.0, 1500));
    left += filter.coefficients[0].size() == 0 ? 1 : 0;
  }
  EXPECT_GE(left, 40);
}

// A random walk's filter is its difference: applied, it gives back the walk's steps (the rows after
// the filter's order), and zero on the rows before it.
TEST(Prewhitening, TurnsAWalkIntoItsSteps) {
  std::mt19937_64 random(20261319);
  const Eigen::Index n = 2000;
  const Eigen::MatrixX2d walk = autoregressive(random, 1.0, n);
  const Prewhitening filter = Prewhitening::fitted(walk);
  ASSERT_FALSE(filter.identity());
  Eigen::VectorXd stacked(2 * n);
  stacked << walk.col(0), walk.col(1);
  const Eigen::VectorXd filtered = filter.applied(stacked);
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd& a = filter.coefficients[static_cast<std::size_t>(c)];
    EXPECT_NEAR(a.sum(), 1.0, 0.02) << "channel " << c;
    const Eigen::Index p = a.size();
    EXPECT_EQ(filtered.segment(c * n, p).squaredNorm(), 0.0);
    // The steps have unit variance; the walk itself wanders by tens.
    const Eigen::VectorXd steps = filtered.segment(c * n + p, n - p);
    EXPECT_NEAR(steps.squaredNorm() / static_cast<double>(n - p), 1.0, 0.1) << "channel " << c;
  }
}

// The filter is marked where the input sensors put white noise in the prediction that it would
// expose: under a random walk of unit steps (whose second differences give sigma_r^2 = 1/3),
// on 2,000 rows, none and 0.01 do not, and a tenth of the steps (sigma_p^2 n = 20) does.
TEST(Prewhitening, OnlyWhereTheInputsPutNoNoiseInThePrediction) {
  std::mt19937_64 random(20261321);
  const Eigen::MatrixX2d walk = autoregressive(random, 1.0, 2000);
  EXPECT_FALSE(exposes_input_noise(walk, Eigen::Array2d::Zero()));
  EXPECT_FALSE(exposes_input_noise(walk, Eigen::Array2d(0.01, 0.0)));
  EXPECT_TRUE(exposes_input_noise(walk, Eigen::Array2d(0.0, 0.1)));
}

}  // namespace
}  // namespace gc
