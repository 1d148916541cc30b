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

TEST(ModelHealth, AUnitErrorReadsBackAsItself) {
  EXPECT_EQ(to_string(ModelHealth::unit_error), "unit_error");
  EXPECT_EQ(model_health_from("unit_error"), ModelHealth::unit_error);
  EXPECT_EQ(model_health_from("far off"), ModelHealth::unknown);
}

// Issue 39: a steady fault whose systematic part sat near 3 x the noise flipped the badge between
// red and amber every second. Once red, it stays red until below 0.8 x 3; once green, until a
// third / 0.8; entering takes the plain thresholds.
TEST(ModelHealth, TheBadgeHasHysteresisAtBothThresholds) {
  const double noise = 1000.0;
  const auto with = [&](double systematic, ModelHealth previous) {
    return model_health(model(systematic, noise, 0.0, noise), 500, previous);
  };
  EXPECT_EQ(with(2900.0, ModelHealth::systematic), ModelHealth::systematic);
  EXPECT_EQ(with(3000.0, ModelHealth::systematic), ModelHealth::far_off);
  EXPECT_EQ(with(2900.0, ModelHealth::far_off), ModelHealth::far_off);
  EXPECT_EQ(with(2401.0, ModelHealth::far_off), ModelHealth::far_off);
  EXPECT_EQ(with(2399.0, ModelHealth::far_off), ModelHealth::systematic);
  // A sequence around 3 x noise shows one change, not one a second.
  ModelHealth shown = ModelHealth::unknown;
  int changes = 0;
  for (double systematic : {3100.0, 2900.0, 3050.0, 2800.0, 3000.0, 2700.0}) {
    const ModelHealth next = with(systematic, shown);
    changes += next != shown;
    shown = next;
  }
  EXPECT_EQ(changes, 1);
  EXPECT_EQ(shown, ModelHealth::far_off);
  // The green side: stays green up to a third / 0.8 of the noise.
  EXPECT_EQ(with(400.0, ModelHealth::at_noise_level), ModelHealth::at_noise_level);
  EXPECT_EQ(with(400.0, ModelHealth::systematic), ModelHealth::systematic);
  EXPECT_EQ(with(420.0, ModelHealth::at_noise_level), ModelHealth::systematic);
  EXPECT_EQ(model_health_from("far_off"), ModelHealth::far_off);
  EXPECT_EQ(model_health_from(""), ModelHealth::unknown);
}

}  // namespace
}  // namespace gc::status
