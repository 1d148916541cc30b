#include "core/rotation_phase.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace gc {
namespace {

std::vector<MeasurementSample> at_times(const std::vector<double>& times) {
  std::vector<MeasurementSample> samples(times.size());
  for (std::size_t i = 0; i < times.size(); ++i) samples[i].time_s = times[i];
  return samples;
}

TEST(RotationPhase, ConstantSpeedTurnsTwoPiRpmOverSixtyPerSecond) {
  // 15 rpm: 2 pi 15 / 60 = pi / 2 rad/s; at uneven times 0, 0.1, 0.35, 1, 4 s.
  std::vector<MeasurementSample> samples = at_times({0.0, 0.1, 0.35, 1.0, 4.0});
  for (MeasurementSample& s : samples) s.speed_rpm = 15.0;
  ASSERT_TRUE(derive_rotation_phase(samples));
  for (const MeasurementSample& s : samples) {
    EXPECT_NEAR(*s.rotation_phase_rad, std::numbers::pi / 2 * s.time_s, 1e-12) << s.time_s;
  }
  EXPECT_NEAR(*samples.back().rotation_phase_rad, 2.0 * std::numbers::pi, 1e-12);  // one turn
}

TEST(RotationPhase, SpeedRampGivesItsIntegral) {
  // n(t) = 60 t rpm, omega = 2 pi t rad/s: phi(t) = pi t^2, which the trapezoid integrates
  // exactly (a linear speed); from t = 2 s, not 0: the phase starts at 0 at the first sample.
  std::vector<MeasurementSample> samples = at_times({2.0, 2.5, 3.0, 3.2, 5.0});
  for (MeasurementSample& s : samples) s.speed_rpm = 60.0 * s.time_s;
  ASSERT_TRUE(derive_rotation_phase(samples));
  for (const MeasurementSample& s : samples) {
    EXPECT_NEAR(*s.rotation_phase_rad, std::numbers::pi * (s.time_s * s.time_s - 4.0), 1e-12)
        << s.time_s;
  }
  EXPECT_NEAR(*samples.back().rotation_phase_rad, 21.0 * std::numbers::pi, 1e-12);
}

TEST(RotationPhase, TrapezoidOfAStepInSpeedAveragesItsEnds) {
  // 0 then 60 rpm (2 pi rad/s) one second later: (0 + 2 pi) / 2 * 1 s = pi.
  std::vector<MeasurementSample> samples = at_times({0.0, 1.0});
  samples[0].speed_rpm = 0.0;
  samples[1].speed_rpm = 60.0;
  ASSERT_TRUE(derive_rotation_phase(samples));
  EXPECT_EQ(*samples[0].rotation_phase_rad, 0.0);
  EXPECT_NEAR(*samples[1].rotation_phase_rad, std::numbers::pi, 1e-15);
}

TEST(RotationPhase, LeftUnsetWhenASampleHasNoSpeed) {
  std::vector<MeasurementSample> samples = at_times({0.0, 1.0, 2.0});
  samples[0].speed_rpm = 10.0;
  samples[2].speed_rpm = 10.0;
  EXPECT_FALSE(derive_rotation_phase(samples));
  for (const MeasurementSample& s : samples) EXPECT_FALSE(s.rotation_phase_rad.has_value());
}

}  // namespace
}  // namespace gc
