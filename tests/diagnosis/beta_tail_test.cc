// The Beta tail that lets the surrogate test stop early (diagnosis/beta_tail.h), against values in
// closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "diagnosis/beta_tail.h"

namespace gc {
namespace {

TEST(BetaTail, IncompleteBetaMatchesClosedForms) {
  for (const double x : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    EXPECT_NEAR(regularized_incomplete_beta(x, 1.0, 1.0), x, 1e-12) << x;                       // uniform
    EXPECT_NEAR(regularized_incomplete_beta(x, 2.0, 1.0), x * x, 1e-12) << x;                   // x^a for b = 1
    EXPECT_NEAR(regularized_incomplete_beta(x, 1.0, 3.0), 1.0 - std::pow(1.0 - x, 3), 1e-12) << x;
  }
  // I_0.5(2, 3) = 11/16; and far in a tail, I_0.9(2, 40) = 1 - 0.1^40 (1 + 40 * 0.9) / ... close to 1.
  EXPECT_NEAR(regularized_incomplete_beta(0.5, 2.0, 3.0), 11.0 / 16.0, 1e-12);
  EXPECT_NEAR(regularized_incomplete_beta(0.3, 5.5, 7.25) + regularized_incomplete_beta(0.7, 7.25, 5.5), 1.0, 1e-12);
}

// The tail of the Beta with given moments, against the share explained of Gaussian noise by one
// random regressor among n rows, which is Beta(1/2, (n - 1)/2) exactly: 20,000 draws.
TEST(BetaTail, TheTailOfAShareExplainedOfGaussianNoise) {
  constexpr int kRows = 40, kDraws = 20000;
  std::mt19937_64 random(20261129);
  std::normal_distribution<double> normal;
  const double a = 0.5, b = (kRows - 1) / 2.0;
  const double mean = a / (a + b), variance = a * b / ((a + b) * (a + b) * (a + b + 1.0));
  for (const double observed : {0.05, 0.1, 0.2}) {
    int beyond = 0;
    for (int d = 0; d < kDraws; ++d) {
      double xy = 0.0, xx = 0.0, yy = 0.0;
      for (int i = 0; i < kRows; ++i) {
        const double x = normal(random), y = normal(random);
        xy += x * y, xx += x * x, yy += y * y;
      }
      beyond += xy * xy / (xx * yy) >= observed;
    }
    const double rate = static_cast<double>(beyond) / kDraws, tail = beta_upper_tail(observed, mean, variance);
    EXPECT_NEAR(rate, tail, 4.0 * std::sqrt(tail * (1.0 - tail) / kDraws) + 1e-4) << observed;
  }
  EXPECT_DOUBLE_EQ(beta_upper_tail(0.01, 0.02, 1e-4), 1.0);  // not above the mean
  EXPECT_DOUBLE_EQ(beta_upper_tail(0.5, 0.2, 0.5), 1.0);     // no Beta has these moments
}

}  // namespace
}  // namespace gc
