#include "core/input_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "diagnosis/synthesis/synthesize.h"

namespace gc {
namespace {

// Holds and ramps of misalignment every 0.05 s, as a test-cell schedule moves it [rad].
std::vector<double> holds_and_ramps(double noise_rad, std::uint64_t seed) {
  std::vector<double> x;
  const double levels[] = {0.002, 0.010, 0.004, 0.012, 0.002};
  for (int segment = 0; segment + 1 < 5; ++segment) {
    for (int i = 0; i < 200; ++i) x.push_back(levels[segment]);                    // hold, 10 s
    for (int i = 0; i < 160; ++i) {                                                 // ramp, 8 s
      x.push_back(levels[segment] + (levels[segment + 1] - levels[segment]) * i / 160.0);
    }
  }
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += noise_rad * standard_normal(seed, i, 0);
  return x;
}

TEST(InputNoise, RecoversWhiteNoiseOnHoldsAndRampsWithinTenPercent) {
  for (std::uint64_t seed : {1, 2, 3}) {
    EXPECT_NEAR(input_noise_sigma(holds_and_ramps(6e-5, seed)), 6e-5, 6e-6) << seed;
  }
}

TEST(InputNoise, HoldsAndRampsAloneAreNoNoise) {
  // Only the 8 corners between holds and ramps have a second difference (of up to 5e-5 rad):
  // 8 of 1,438 values do not move the median.
  EXPECT_LT(input_noise_sigma(holds_and_ramps(0.0, 1)), 1e-12);
}

TEST(InputNoise, ShortSeriesFollowTheFormulaByHand) {
  // 1.4826 MAD(d) / sqrt(6), d_i = x_{i-1} - 2 x_i + x_{i+1}.
  const std::vector<double> x{0.0, 1.0, 0.0};  // d = 0 - 2 + 0 = -2
  EXPECT_DOUBLE_EQ(input_noise_sigma(x), 0.0);  // MAD about its own median is 0
  const std::vector<double> y{0.0, 1.0, 0.0, 0.0};  // d = -2, 1: median -0.5, MAD 1.5
  EXPECT_NEAR(input_noise_sigma(y), 1.4826 * 1.5 / std::sqrt(6.0), 1e-15);
  EXPECT_EQ(input_noise_sigma(std::vector<double>{1.0, 2.0}), 0.0);  // fewer than three
}

}  // namespace
}  // namespace gc
