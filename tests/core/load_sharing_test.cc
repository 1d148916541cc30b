#include "core/load_sharing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/model_error.h"

namespace gc {
namespace {

TEST(LoadSharing, Eq22BranchesJoinContinuously) {
  EXPECT_NEAR(load_sharing_ratio(0.4 - 1e-12), load_sharing_ratio(0.4), 2e-3);  // 0.2842 vs 0.284
  EXPECT_NEAR(load_sharing_ratio(1.0 - 1e-12), load_sharing_ratio(1.0), 1e-9);  // both 0.5
  EXPECT_NEAR(load_sharing_ratio(0.0), std::sqrt(1.195) - 1.033, 1e-15);
  EXPECT_DOUBLE_EQ(load_sharing_ratio(std::numeric_limits<double>::infinity()), 1.0);
  EXPECT_DOUBLE_EQ(load_sharing_ratio(2.0), 0.75);  // 1 - 1 / (2 x)
}

TEST(LoadSharing, Eq22IsIncreasingInX) {
  double previous = load_sharing_ratio(0.0);
  for (double x = 0.01; x < 20.0; x += 0.01) {
    const double q = load_sharing_ratio(x);
    EXPECT_GE(q, previous - 1e-3) << x;  // the 0.4 joint steps down by 2.4e-4 as printed
    previous = q;
  }
}

TEST(LoadSharing, IterationMeetsItsTolerance) {
  // Upwind at 1.5 MN·m and 0.5 deg: P_t' = 31.42 kN, C = 1.4635e9 N/m, z_o = 2.79e-5 m.
  const LoadSharingOptions options{1e-12, 100};
  const double mean = 1.5e6 / (0.508 * std::cos(20 * M_PI / 180)) / 100;
  const double zo = 2.585159 * std::sin(20 * M_PI / 180) * std::pow(std::tan(0.5 * M_PI / 180), 2) /
                    (2 * std::tan(20 * M_PI / 180));
  const LoadSharing s = solve_load_sharing(mean, 1.4635e9, zo, options);
  EXPECT_NEAR(load_sharing_ratio(mean / (s.q * 1.4635e9 * zo)), s.q, 1e-12);
  EXPECT_NEAR(s.q, 0.367, 1e-3);  // independent bisection in Python: 0.3674
  EXPECT_LE(s.iterations, 20);
}

TEST(LoadSharing, AlignedCouplingSharesEqually) {
  const LoadSharing s = solve_load_sharing(31e3, 1.46e9, 0.0, {});
  EXPECT_DOUBLE_EQ(s.q, 1.0);
  EXPECT_TRUE(std::isinf(s.ze_over_zo));
}

TEST(LoadSharing, NonConvergenceIsAnErrorNotAValue) {
  EXPECT_THROW(solve_load_sharing(31e3, 1.46e9, 2.8e-5, {1e-15, 1}), NotConverged);
}

TEST(LoadSharing, RejectsNonsenseOptions) {
  EXPECT_THROW(solve_load_sharing(31e3, 1.46e9, 2.8e-5, {0.0, 10}), InvalidInput);
  EXPECT_THROW(solve_load_sharing(31e3, 1.46e9, 2.8e-5, {1e-6, 0}), InvalidInput);
}

}  // namespace
}  // namespace gc
