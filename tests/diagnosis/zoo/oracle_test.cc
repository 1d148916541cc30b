// The oracle's bound (oracle.h) against what is known in closed form: Burg's fit of an AR(1), the
// known-signal detectability s' Sigma^-1 s under white noise and under an AR(1), and a random walk
// under which a constant offset cannot be told from the walk's level while a fast ripple can.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "tests/diagnosis/zoo/oracle.h"

namespace gc::zoo {
namespace {

std::vector<double> ar1(std::size_t n, double phi, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> e(0.0, sigma);
  std::vector<double> x(n);
  double v = 0.0;
  for (auto& xi : x) xi = v = phi * v + e(rng);
  return x;
}

TEST(ZooOracle, BurgRecoversAnAutoregressionOfOrderOne) {
  const Autoregression fit = burg(ar1(20000, 0.9, 2.0, 1), 1);
  ASSERT_EQ(fit.a.size(), 1u);
  EXPECT_NEAR(fit.a[0], -0.9, 0.01);                 // x_t - 0.9 x_{t-1} = e_t
  EXPECT_NEAR(fit.innovation_variance, 4.0, 0.15);   // sigma^2 = 4
}

TEST(ZooOracle, UnderWhiteNoiseTheBoundIsTheSignalsEnergyOverTheNoisesVariance) {
  const std::size_t n = 4000;
  const std::vector<double> noise_y = ar1(n, 0.0, 3.0, 2), noise_z = ar1(n, 0.0, 3.0, 3);
  std::vector<double> sy(n), sz(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) sy[i] = 0.15 * std::sin(2 * std::numbers::pi * i / 400.0);
  const OracleBound b = oracle_bound(sy, sz, noise_y, noise_z);
  const double expected = std::sqrt(n * 0.5 * 0.15 * 0.15 / 9.0);   // 2.0
  EXPECT_NEAR(b.d, expected, 0.05 * expected);
  EXPECT_NEAR(b.power, 0.5 * std::erfc(-(expected - 2.3263) / std::sqrt(2.0)), 0.04);
}

TEST(ZooOracle, UnderAnAutoregressionAnOffsetCountsOneMinusPhiOfItsRows) {
  // s' Sigma^-1 s for a constant c under an AR(1): about (n - 1) (1 - phi)^2 c^2 / sigma_e^2.
  const std::size_t n = 20000;
  const double phi = 0.95, sigma = 1.0, c = 0.2;
  const std::vector<double> noise = ar1(n, phi, sigma, 4), quiet = ar1(n, 0.0, 1.0, 5);
  const std::vector<double> offset(n, c), none(n, 0.0);
  const OracleBound b = oracle_bound(offset, none, noise, quiet);
  const double expected = std::sqrt((n - 1) * (1 - phi) * (1 - phi) * c * c / (sigma * sigma));   // 1.41
  EXPECT_NEAR(b.d, expected, 0.1 * expected);
}

TEST(ZooOracle, UnderARandomWalkAnOffsetIsHiddenAndAFastRippleIsNot) {
  const std::size_t n = 5000;
  const std::vector<double> walk = ar1(n, 1.0, 1.0, 6), quiet = ar1(n, 0.0, 1.0, 7);
  double rms = 0.0;
  for (double w : walk) rms += w * w;
  rms = std::sqrt(rms / n);   // tens: the walk's spread
  const std::vector<double> none(n, 0.0), offset(n, 1.5 * rms);
  std::vector<double> ripple(n);
  for (std::size_t i = 0; i < n; ++i) ripple[i] = 0.5 * std::sin(2 * std::numbers::pi * i / 4.0);
  EXPECT_LT(oracle_bound(offset, none, walk, quiet).d, 3.61);   // 1.5 times the walk's RMS, yet hidden
  EXPECT_GT(oracle_bound(ripple, none, walk, quiet).d, 20.0);  // half the step's sigma, every row
}

TEST(ZooOracle, ANoiseCommonToBothChannelsCountsOnceAndPartsWhatMovesThemApart) {
  const std::size_t n = 4000;
  const std::vector<double> common = ar1(n, 0.0, 3.0, 8), own_y = ar1(n, 0.0, 0.3, 9), own_z = ar1(n, 0.0, 0.3, 10);
  std::vector<double> ny(n), nz(n), same(n), apart_y(n), apart_z(n);
  for (std::size_t i = 0; i < n; ++i) {
    ny[i] = common[i] + own_y[i];
    nz[i] = common[i] + own_z[i];
    same[i] = 0.15 * std::sin(2 * std::numbers::pi * i / 400.0);
    apart_y[i] = same[i], apart_z[i] = -same[i];
  }
  const double one = std::sqrt(n * 0.5 * 0.15 * 0.15 / (9.0 + 0.09));   // one channel's d, 2.0
  // The same signal on both under one noise: no more than one channel tells (sqrt 2 x if independent).
  EXPECT_NEAR(oracle_bound(same, same, ny, nz).d, one, 0.1 * one);
  // Opposite signals: the common noise cancels in their difference, 0.3 of own noise is left.
  EXPECT_GT(oracle_bound(apart_y, apart_z, ny, nz).d, 10 * one);
}

TEST(ZooOracle, RefusesSeriesOfUnequalLengthOrNotFinite) {
  const std::vector<double> a(100, 0.0), b(99, 0.0);
  EXPECT_THROW(oracle_bound(a, a, a, b), std::invalid_argument);
  std::vector<double> c(100, 0.0);
  c[10] = std::nan("");
  EXPECT_THROW(oracle_bound(a, a, c, a), std::invalid_argument);
}

}  // namespace
}  // namespace gc::zoo
