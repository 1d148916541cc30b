// The model-health badge (clients/status/model_health.h) at its thresholds: green while the
// systematic part is under a third of the noise, red from three times the noise, amber between;
// the worse channel decides; grey before the window holds two samples.
#include "clients/status/model_health.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gc::status {
namespace {

namespace v1 = ::gearcoupling::v1;

v1::ModelPeriodRecord model(double msy_systematic, double msy_noise, double msz_systematic,
                            double msz_noise) {
  v1::ModelPeriodRecord m;
  m.mutable_msy()->set_systematic_nm(msy_systematic);
  m.mutable_msy()->set_noise_nm(msy_noise);
  m.mutable_msz()->set_systematic_nm(msz_systematic);
  m.mutable_msz()->set_noise_nm(msz_noise);
  return m;
}

TEST(ModelHealth, GreenBelowAThirdOfTheNoiseAmberFromIt) {
  const double noise = 1900.0;
  const double third = kAtNoiseLevelShare * noise;
  EXPECT_EQ(channel_health(std::nextafter(third, 0.0), noise), ModelHealth::at_noise_level);
  EXPECT_EQ(channel_health(third, noise), ModelHealth::systematic);
  EXPECT_EQ(channel_health(0.0, noise), ModelHealth::at_noise_level);
}

TEST(ModelHealth, RedFromThreeTimesTheNoiseAmberBelow) {
  const double noise = 1900.0;
  EXPECT_EQ(channel_health(std::nextafter(kFarOffRatio * noise, 0.0), noise),
            ModelHealth::systematic);
  EXPECT_EQ(channel_health(kFarOffRatio * noise, noise), ModelHealth::far_off);
  // Issue 25's cell: 6.6 kN·m systematic against 1.9 kN·m of noise showed only "alive".
  EXPECT_EQ(channel_health(6600.0, 1900.0), ModelHealth::far_off);
}

TEST(ModelHealth, NoNoiseIsGreenOnlyWithoutError) {
  EXPECT_EQ(channel_health(0.0, 0.0), ModelHealth::at_noise_level);
  EXPECT_EQ(channel_health(1.0, 0.0), ModelHealth::far_off);
}

TEST(ModelHealth, TheWorseChannelDecides) {
  EXPECT_EQ(model_health(model(100, 1000, 100, 1000), 500), ModelHealth::at_noise_level);
  EXPECT_EQ(model_health(model(100, 1000, 1000, 1000), 500), ModelHealth::systematic);
  EXPECT_EQ(model_health(model(3000, 1000, 100, 1000), 500), ModelHealth::far_off);
  EXPECT_EQ(to_string(model_health(model(3000, 1000, 100, 1000), 500)), "far_off");
}

TEST(ModelHealth, UnknownBeforeTwoSamples) {
  EXPECT_EQ(model_health(model(3000, 1000, 100, 1000), 1), ModelHealth::unknown);
  EXPECT_EQ(model_health(model(0, 0, 0, 0), 2), ModelHealth::at_noise_level);
  EXPECT_EQ(to_string(ModelHealth::unknown), "unknown");
}

}  // namespace
}  // namespace gc::status
