// The noise of a residual as test cells have it (diagnosis/noise_estimate.h): sigma and the
// lag-1 autocorrelation from the variogram fit, and spikes found by the running median.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "diagnosis/noise_estimate.h"
#include "diagnosis/synthesis/synthesize.h"

namespace gc {
namespace {

constexpr int kRows = 4000;

/// AR(1) with marginal standard deviation sigma on both channels (phi 0: white).
Eigen::MatrixX2d ar1(double sigma, double phi, std::uint64_t seed) {
  Eigen::MatrixX2d r(kRows, 2);
  const double innovation = sigma * std::sqrt(1.0 - phi * phi);
  for (int c = 0; c < 2; ++c) {
    double x = sigma * standard_normal(seed, 0, static_cast<std::uint64_t>(c));
    for (int i = 0; i < kRows; ++i) {
      if (i > 0) x = phi * x + innovation * standard_normal(seed, static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(c));
      r(i, c) = x;
    }
  }
  return r;
}

TEST(NoiseEstimate, FindsSigmaOfWhiteNoiseAndNoCorrelation) {
  const NoiseEstimate n = estimate_noise(ar1(2000.0, 0.0, 3));
  EXPECT_NEAR(n.sigma_nm(0), 2000.0, 100.0);
  EXPECT_NEAR(n.sigma_nm(1), 2000.0, 100.0);
  EXPECT_LT(n.phi.maxCoeff(), 0.1);
  EXPECT_LT(n.variance_inflation(), 1.25);
}

// Successive differences alone would see sigma sqrt(1 - phi) = 0.45 sigma here: the fit of the
// variogram over ten lags sees the whole marginal sigma and the correlation.
TEST(NoiseEstimate, FindsSigmaAndCorrelationOfColouredNoise) {
  const NoiseEstimate n = estimate_noise(ar1(2000.0, 0.8, 5));
  EXPECT_NEAR(n.sigma_nm(0), 2000.0, 250.0);
  EXPECT_NEAR(n.sigma_nm(1), 2000.0, 250.0);
  EXPECT_NEAR(n.phi(0), 0.8, 0.08);
  EXPECT_NEAR(n.phi(1), 0.8, 0.08);
  EXPECT_GT(n.variance_inflation(), 6.0);
}

// A slow structure (a ramp and a slow sine of 20 kN·m) adds b h + c h^2 to the variogram, not
// to sigma.
TEST(NoiseEstimate, IsNotInflatedBySlowStructure) {
  Eigen::MatrixX2d r = ar1(2000.0, 0.0, 7);
  for (int i = 0; i < kRows; ++i) {
    r(i, 0) += 10.0 * i;
    r(i, 1) += 20000.0 * std::sin(2.0 * M_PI * i / 1000.0);
  }
  const NoiseEstimate n = estimate_noise(r);
  EXPECT_NEAR(n.sigma_nm(0), 2000.0, 150.0);
  EXPECT_NEAR(n.sigma_nm(1), 2000.0, 150.0);
}

// A channel's level against its long-run standard error (level_standard_errors): correlated noise
// about zero stays within 4.5 errors at the rate a calibrated test allows, over 200 fresh draws of
// white and AR(1) noise at phi 0.9 and 0.98 (a naive error, sqrt(variance / n), is ten times too
// small at 0.98 and puts most of its levels past 4.5); an offset of a fifth of a white noise's sigma
// over 4,000 rows stands far out.
TEST(NoiseEstimate, TellsALevelFromCorrelatedNoiseAboutZero) {
  int beyond = 0, draws = 0;
  for (const double phi : {0.0, 0.9, 0.98}) {
    for (std::uint64_t seed = 1; seed <= 200; ++seed, ++draws) {
      beyond += level_standard_errors(ar1(1000.0, phi, 9000 + seed)) > 4.5;
    }
  }
  EXPECT_LE(beyond, 2) << "of " << draws;
  Eigen::MatrixX2d offset = ar1(1000.0, 0.0, 77);
  offset.col(0).array() += 200.0;
  EXPECT_GT(level_standard_errors(offset), 8.0);
  EXPECT_EQ(level_standard_errors(ar1(1000.0, 0.0, 78).topRows(99)), 0.0);  // too few rows to say
}

TEST(NoiseEstimate, FlagsSpikesButNotStepsOrColouredNoise) {
  Eigen::MatrixX2d r = ar1(2000.0, 0.8, 11);
  // A step of 16 kN·m every 200 rows (an effect that flips with the direction of travel).
  for (int i = 0; i < kRows; ++i) r(i, 0) += (i / 200) % 2 ? 8000.0 : -8000.0;
  EXPECT_TRUE(outlier_positions(r).empty());
  // 1 % spikes at 10 sigma.
  std::vector<std::size_t> spikes;
  for (int i = 50; i < kRows; i += 100) {
    r(i, i % 200 < 100 ? 0 : 1) += (i % 300 < 150 ? 1.0 : -1.0) * 20000.0;
    spikes.push_back(static_cast<std::size_t>(i));
  }
  const std::vector<std::size_t> found = outlier_positions(r);
  // Every flag a spike; nearly every spike flagged: one whose neighbour the AR(1) noise carries out
  // beyond half the threshold is kept with its neighbours as possible structure (a ringing's
  // peaks stand alone above the threshold with their neighbours just below it).
  for (std::size_t f : found) EXPECT_TRUE(std::binary_search(spikes.begin(), spikes.end(), f)) << f;
  EXPECT_GE(found.size(), spikes.size() * 90 / 100);
}

}  // namespace
}  // namespace gc
