// The fitting engine on problems with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "diagnosis/bounded_least_squares.h"
#include "diagnosis/parameter_identifiability.h"

namespace gc {
namespace {

/// y = a exp(-b t) at 20 points, a = 0.7, b = 0.3 (both in the unit box), no noise.
ResidualFunction decay(double a, double b) {
  return [a, b](const Eigen::VectorXd& x) -> std::optional<Eigen::VectorXd> {
    Eigen::VectorXd r(20);
    for (int i = 0; i < 20; ++i) r(i) = a * std::exp(-b * i * 0.2) - x(0) * std::exp(-x(1) * i * 0.2);
    return r;
  };
}

TEST(BoundedLeastSquares, RecoversAnExponentialDecayToSixDigits) {
  LeastSquaresOptions options;
  options.max_iterations = 50;
  options.difference_step = 1e-6;
  const LeastSquaresResult r = bounded_least_squares(decay(0.7, 0.3), Eigen::Vector2d(0.2, 0.9), options);
  EXPECT_NEAR(r.x(0), 0.7, 1e-6);
  EXPECT_NEAR(r.x(1), 0.3, 1e-6);
  EXPECT_LT(r.cost, 1e-12);
}

TEST(BoundedLeastSquares, StopsAtTheBoundWhenTheOptimumLiesOutside) {
  // The true amplitude 1.4 lies outside the box: the fit holds a at 1 and fits b as well as it can.
  LeastSquaresOptions options;
  options.max_iterations = 50;
  const LeastSquaresResult r = bounded_least_squares(decay(1.4, 0.3), Eigen::Vector2d(0.5, 0.5), options);
  EXPECT_DOUBLE_EQ(r.x(0), 1.0);
  EXPECT_GE(r.x(1), 0.0);
  EXPECT_LE(r.x(1), 1.0);
}

TEST(BoundedLeastSquares, RejectsSteppingWhereTheModelCannotBeEvaluated) {
  // Evaluable only for x < 0.6: the fit approaches the edge from inside and never returns there.
  const ResidualFunction f = [](const Eigen::VectorXd& x) -> std::optional<Eigen::VectorXd> {
    if (x(0) >= 0.6) return std::nullopt;
    return Eigen::VectorXd::Constant(1, 0.9 - x(0));
  };
  const LeastSquaresResult r = bounded_least_squares(f, Eigen::VectorXd::Constant(1, 0.1));
  EXPECT_LT(r.x(0), 0.6);
  EXPECT_GT(r.x(0), 0.4);
}

TEST(ParameterIdentifiability, FlagsTheLaterOfTwoParametersThatOnlyEnterAsAProduct) {
  // r = y - p q t: the columns of p and q are proportional, as friction's mu_low_torque and T_ref.
  Eigen::MatrixXd j(10, 3);
  for (int i = 0; i < 10; ++i) j.row(i) << 1.0, 0.5 * i, 0.25 * i;
  const auto u = find_unidentifiable(j, {true, true, true});
  ASSERT_TRUE(u.has_value());
  EXPECT_EQ(u->parameter, 2);
  EXPECT_EQ(u->partner, 1);
  EXPECT_NEAR(u->correlation, 1.0, 1e-12);
  EXPECT_FALSE(find_unidentifiable(j, {true, true, false}).has_value());
}

}  // namespace
}  // namespace gc
