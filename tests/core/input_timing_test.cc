// Inputs read late and averaged (core/input_timing.h), as moment_delay reads them: the window
// (t_i - delay - average, t_i - delay] holds the same samples whichever side of t_i it lies on.
#include "core/input_timing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "tests/core/nrel_couplings.h"

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

/// A recording at `per_second` samples a second: a torque ramp, a misalignment that swells, a
/// direction that turns a revolution in 40 s, the shaft at 10 rpm (a revolution in 6 s).
std::vector<RecordedSample> turning(int count, double per_second) {
  std::vector<RecordedSample> r(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    MeasurementSample& s = r[static_cast<std::size_t>(k)].input;
    s.time_s = k / per_second;
    s.torque_nm = 8.0e5 + 2.0e3 * s.time_s;
    s.misalignment_rad = 1.5e-3 + 1.0e-3 * std::sin(0.3 * s.time_s);
    s.direction_rad = std::remainder(0.157 * s.time_s, 6.283185307179586);
    s.speed_rpm = 10.0;
  }
  return r;
}

// The window's inputs read from columns computed once (WindowColumns) are those it computes itself,
// to the bit, whichever side of t_i the window lies on, where the columns cover it, part of it
// (their first and last samples inside the window) or none of it.
TEST(InputTiming, AWindowReadFromColumnsIsTheSameToTheBit) {
  const std::vector<RecordedSample> r = turning(400, 20.0);
  const WindowColumns columns(r, 100, 299);
  for (const double delay : {1.3, 0.0, -0.7}) {
    for (const double average : {0.3, 4.1}) {
      for (std::size_t i = 0; i < r.size(); i += 7) {
        const MeasurementSample own = timed_input(std::span<const RecordedSample>(r), i, {delay, average});
        const MeasurementSample read = timed_input(std::span<const RecordedSample>(r), i, {delay, average}, &columns);
        EXPECT_EQ(read.torque_nm, own.torque_nm) << "i " << i << ", delay " << delay << ", average " << average;
        EXPECT_EQ(read.misalignment_rad, own.misalignment_rad) << "i " << i << ", delay " << delay;
        EXPECT_EQ(read.direction_rad, own.direction_rad) << "i " << i << ", delay " << delay;
      }
    }
  }
}

// moments_at reads the windows of a long average from columns (two revolutions at 10 rpm: 600
// samples each at 50 Hz) and gives predict_at's moments to the bit; a short average reads the
// recording itself.
TEST(InputTiming, MomentsAtRowsWithALongAverageArePredictAtsToTheBit) {
  const std::vector<RecordedSample> r = turning(2000, 50.0);
  const CouplingModel paper(testing::nrel_upwind(), {make_effect("friction", {{"mu0", 0.1}}),
                                                     make_effect("pressure_angle_rotation")});
  const CouplingModel lagged = paper.with_effect(make_effect("moment_delay", {{"delay_s", -0.3}, {"averaging_revolutions", 2.0}}));
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < r.size(); i += 3) rows.push_back(i);
  ASSERT_TRUE(lagged.window_columns(r, rows).has_value());
  const CouplingModel::MomentsAtRows m = lagged.moments_at(r, rows);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_TRUE(m.errors[k].empty()) << m.errors[k];
    const SensorMoments one = lagged.predict_at(std::span<const RecordedSample>(r), rows[k]).moments;
    EXPECT_EQ(m.moments[k].y_nm, one.y_nm) << "row " << rows[k];
    EXPECT_EQ(m.moments[k].z_nm, one.z_nm) << "row " << rows[k];
  }
  const CouplingModel brief = paper.with_effect(make_effect("moment_delay", {{"delay_s", -0.3}, {"averaging_revolutions", 0.001}}));
  EXPECT_FALSE(brief.window_columns(r, rows).has_value());
}

}  // namespace
}  // namespace gc
