// Inputs read late and averaged (core/input_timing.h), as moment_delay reads them: the window
// (t_i - delay - average, t_i - delay] holds the same samples whichever side of t_i it lies on.
#include "core/input_timing.h"

#include <gtest/gtest.h>

#include <vector>

namespace gc {
namespace {

/// Samples every 0.1 s from t = 0, the torque equal to 1000 N·m times the time in seconds.
std::vector<MeasurementSample> ramp(int count) {
  std::vector<MeasurementSample> s(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    s[static_cast<std::size_t>(k)].time_s = 0.1 * k;
    s[static_cast<std::size_t>(k)].torque_nm = 100.0 * k;
    s[static_cast<std::size_t>(k)].misalignment_rad = 1e-3;
  }
  return s;
}

TEST(InputTiming, ADelayReadsTheInputsThatLongBefore) {
  const std::vector<MeasurementSample> s = ramp(50);
  const MeasurementSample late = timed_input(s, 20, {0.35, 0.0});
  EXPECT_NEAR(late.torque_nm, 1650.0, 1e-9);  // t = 2.0 - 0.35, between samples
  EXPECT_EQ(late.time_s, s[20].time_s);
  EXPECT_TRUE(late.inputs_timed);
  const MeasurementSample early = timed_input(s, 20, {-0.35, 0.0});
  EXPECT_NEAR(early.torque_nm, 2350.0, 1e-9);
}

// The mean over a window of a ramp is the ramp at the window's centre, for a delay of either sign:
// the point at the window's end (interpolated, as without averaging) and the samples in it.
TEST(InputTiming, TheAverageWindowEndsAtTheDelayedTimeOnEitherSide) {
  const std::vector<MeasurementSample> s = ramp(60);
  const int i = 30;  // t_i = 3.0 s
  for (const double delay : {0.5, 0.0, -0.5, -1.0}) {
    const double end = 3.0 - delay;
    // The interpolated point at `end` and the samples in (end - 0.4, end]: 4 or 5 of them.
    double sum = 1000.0 * end, count = 1.0;
    for (int k = 0; k < 60; ++k) {
      const double t = 0.1 * k;
      if (t > end - 0.4 + 1e-12 && t <= end + 1e-12) {
        sum += 1000.0 * t;
        count += 1.0;
      }
    }
    const MeasurementSample averaged = timed_input(s, static_cast<std::size_t>(i), {delay, 0.4});
    EXPECT_NEAR(averaged.torque_nm, sum / count, 1e-6) << "delay " << delay << " s";
    EXPECT_GT(averaged.torque_nm, 1000.0 * (end - 0.4)) << "delay " << delay << " s";
    EXPECT_LE(averaged.torque_nm, 1000.0 * end + 1e-9) << "delay " << delay << " s";
  }
}

}  // namespace
}  // namespace gc
