#include "core/load_sharing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/model_error.h"

namespace gc {
namespace {

/// Options with a tolerance and an iteration limit, never cancelled.
LoadSharingOptions limits(double tolerance, int max_iterations) {
  LoadSharingOptions options;
  options.tolerance = tolerance;
  options.max_iterations = max_iterations;
  return options;
}

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
  const LoadSharingOptions options = limits(1e-12, 100);
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

// On eq 22's root branch (x < 0.4: a light load for the misalignment, here x0 = P_t' / (C z_o) =
// 0.01) the iteration starts a few per cent off the fixed point: one step cannot reach 1e-15.
constexpr double kRootBranchLoadN = 409.0;

TEST(LoadSharing, NonConvergenceIsAnErrorNotAValue) {
  EXPECT_THROW(solve_load_sharing(kRootBranchLoadN, 1.46e9, 2.8e-5, limits(1e-15, 1)), NotConverged);
}

/// Eq 22's fixed point by bisection, written apart from the solver.
double bisected_q(double x0) {
  double lo = load_sharing_ratio(0.0), hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (load_sharing_ratio(x0 / mid) - mid > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Started where the fixed point lies (in closed form on the linear and hyperbolic branches, eq
// 22's x >= 0.4), the secant meets the tolerance in one step there and in a few on the root
// branch, where the paper's start at q = 1 took 5-9; q is the bisection's within the tolerance.
TEST(LoadSharing, StartsAtTheFixedPointAndReachesItInAFewSteps) {
  const double stiffness = 1.46e9, separation = 2.8e-5;
  for (const double x0 : {1e-6, 1e-3, 0.01, 0.03, 0.1, 0.2, 0.3, 0.5, 0.758, 1.0, 2.0, 20.0}) {
    const LoadSharing s = solve_load_sharing(x0 * stiffness * separation, stiffness, separation, limits(1e-12, 100));
    EXPECT_NEAR(s.q, bisected_q(x0), 1e-11) << x0;
    const bool closed_form = s.ze_over_zo >= 0.4;
    EXPECT_LE(s.iterations, closed_form ? 1 : 6) << x0 << ", x " << s.ze_over_zo;
  }
}

TEST(LoadSharing, RejectsNonsenseOptions) {
  EXPECT_THROW(solve_load_sharing(31e3, 1.46e9, 2.8e-5, limits(0.0, 10)), InvalidInput);
  EXPECT_THROW(solve_load_sharing(31e3, 1.46e9, 2.8e-5, limits(1e-6, 0)), InvalidInput);
}

/// The InvalidInput `options` raise: its field and message.
std::pair<std::string, std::string> rejection(const LoadSharingOptions& options) {
  try {
    solve_load_sharing(31e3, 1.46e9, 2.8e-5, options);
  } catch (const InvalidInput& e) {
    return {e.field(), e.what()};
  }
  return {"(accepted)", ""};
}

TEST(LoadSharing, IterationsAreBoundedSoNoRequestRunsForever) {
  // Issue 9: 2147483647 iterations with an unreachable tolerance held a worker indefinitely.
  const auto [field, message] = rejection(limits(1e-9, 2147483647));
  EXPECT_EQ(field, "options.load_sharing.max_iterations");
  EXPECT_NE(message.find("2147483647"), std::string::npos) << message;
  EXPECT_NE(message.find("allowed [1, 10000]"), std::string::npos) << message;
  EXPECT_EQ(rejection(limits(1e-9, kMaxLoadSharingIterations + 1)).first,
            "options.load_sharing.max_iterations");
  EXPECT_NO_THROW(solve_load_sharing(31e3, 1.46e9, 2.8e-5, limits(1e-9, kMaxLoadSharingIterations)));
}

TEST(LoadSharing, ToleranceOutsideItsRangeIsRejectedNamingIt) {
  for (double tolerance : {1e308, 2e-3, 1e-16, 1e-300, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
    const auto [field, message] = rejection(limits(tolerance, 100));
    EXPECT_EQ(field, "options.load_sharing.tolerance") << tolerance;
    EXPECT_NE(message.find("allowed [1e-15, 0.001]"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(solve_load_sharing(31e3, 1.46e9, 2.8e-5, limits(kMinLoadSharingTolerance, 100)));
  EXPECT_NO_THROW(solve_load_sharing(31e3, 1.46e9, 2.8e-5, limits(kMaxLoadSharingTolerance, 100)));
}

TEST(LoadSharing, CancelPredicateIsAskedBeforeEveryIterationAndStopsTheSolve) {
  int asked = 0;
  LoadSharingOptions options = limits(1e-15, 100);
  options.cancelled = [&asked] { return ++asked == 2; };
  EXPECT_THROW(solve_load_sharing(kRootBranchLoadN, 1.46e9, 2.8e-5, options), Cancelled);
  EXPECT_EQ(asked, 2);  // stopped at once, not at the end
}

TEST(LoadSharing, CancelPredicateThatNeverFiresChangesNothing) {
  LoadSharingOptions plain = limits(1e-12, 100);
  LoadSharingOptions watched = plain;
  int asked = 0;
  watched.cancelled = [&asked] {
    ++asked;
    return false;
  };
  const LoadSharing a = solve_load_sharing(31e3, 1.46e9, 2.8e-5, plain);
  const LoadSharing b = solve_load_sharing(31e3, 1.46e9, 2.8e-5, watched);
  EXPECT_EQ(a.q, b.q);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(asked, b.iterations);
}

}  // namespace
}  // namespace gc
