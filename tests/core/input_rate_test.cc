// The inputs' rates (core/input_rate.h): the window's slope, none before the window has samples,
// less noise than a difference, and the same sample by sample as over a whole recording.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <random>
#include <vector>

#include "core/input_rate.h"

namespace gc {
namespace {

TEST(InputRate, IsTheSlopeOfARampFromTheThirdSampleOn) {
  InputRateTracker rate;
  EXPECT_FALSE(rate.next(0.0, 1.0).has_value());
  EXPECT_FALSE(rate.next(0.1, 1.3).has_value());
  for (int i = 2; i < 20; ++i) {
    const double t = 0.1 * i;
    const std::optional<double> r = rate.next(t, 1.0 + 3.0 * t);
    ASSERT_TRUE(r.has_value()) << i;
    EXPECT_NEAR(*r, 3.0, 1e-9) << i;
  }
  // At large times too (the slope is taken about the window's means).
  InputRateTracker late;
  for (int i = 0; i < 10; ++i) late.next(1e6 + 0.1 * i, -2.0 * 0.1 * i);
  EXPECT_NEAR(*late.next(1e6 + 1.0, -2.0), -2.0, 1e-6);
}

TEST(InputRate, FollowsASineWithHalfTheWindowsLagAndLessNoiseThanADifference) {
  std::mt19937_64 random(5);
  std::normal_distribution<double> noise(0.0, 1e-4);
  InputRateTracker rate;
  double err2 = 0.0, diff2 = 0.0, previous = 0.0;
  int n = 0;
  for (int i = 0; i < 4000; ++i) {
    const double t = 0.1 * i;
    const double v = 0.01 * std::sin(2.0 * M_PI * t / 40.0) + noise(random);
    const std::optional<double> r = rate.next(t, v);
    const double truth = 0.01 * 2.0 * M_PI / 40.0 * std::cos(2.0 * M_PI * (t - 0.25) / 40.0);  // half the window late
    if (r && i > 10) {
      err2 += (*r - truth) * (*r - truth);
      diff2 += ((v - previous) / 0.1 - truth) * ((v - previous) / 0.1 - truth);
      ++n;
    }
    previous = v;
  }
  const double rms = std::sqrt(err2 / n), difference_rms = std::sqrt(diff2 / n);
  EXPECT_NEAR(rms, 2.4e-4, 0.4e-4) << "sigma / sqrt(sum (t - mean)^2) for 6 samples over 0.5 s";
  EXPECT_GT(difference_rms, 5.0 * rms);
}

TEST(InputRate, DerivedOverARecordingEqualsTheTrackerSampleBySample) {
  std::vector<MeasurementSample> samples(30);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i].time_s = 0.1 * static_cast<double>(i);
    samples[i].misalignment_rad = 0.001 * std::sqrt(static_cast<double>(i));
    samples[i].torque_nm = 1e6 + 5e4 * static_cast<double>(i * i);
  }
  derive_input_rates(samples);
  InputRateTracker zeta, torque;
  for (const MeasurementSample& s : samples) {
    EXPECT_EQ(s.misalignment_rate_rad_s, zeta.next(s.time_s, s.misalignment_rad));
    EXPECT_EQ(s.torque_rate_nm_s, torque.next(s.time_s, s.torque_nm));
  }
  EXPECT_FALSE(samples[1].torque_rate_nm_s.has_value());
  ASSERT_TRUE(samples[29].torque_rate_nm_s.has_value());
  // The window holds i = 24..29: the slope of 5e4 i^2 over it is d/dt at its middle, i = 26.5.
  EXPECT_NEAR(*samples[29].torque_rate_nm_s, 2.0 * 5e4 * 26.5 / 0.1, 1e-3);
}

// The tracker keeps running sums (O(1) a sample): at 10 kHz, an hour into a test, over 5000
// samples a window, its slope matches the slope computed afresh about the window's means.
TEST(InputRate, RunningSumsMatchTheSlopeComputedAfreshOverALongFastStream) {
  InputRateTracker tracker;
  std::deque<std::pair<double, double>> window;
  const double rate_hz = 10000.0, start_s = 3600.0;
  double worst = 0.0;
  for (int i = 0; i < 30000; ++i) {
    const double t = start_s + i / rate_hz;
    const double v = 1e6 + 2e5 * std::sin(0.7 * t) + 300.0 * std::sin(977.0 * i);  // torque-like
    const std::optional<double> rate = tracker.next(t, v);
    window.emplace_back(t, v);
    while (window.front().first < t - 0.5 * (1.0 + 1e-9)) window.pop_front();
    if (window.size() < 3) continue;
    double mt = 0.0, mv = 0.0;
    for (const auto& [wt, wv] : window) { mt += wt; mv += wv; }
    mt /= static_cast<double>(window.size());
    mv /= static_cast<double>(window.size());
    double stt = 0.0, stv = 0.0;
    for (const auto& [wt, wv] : window) { stt += (wt - mt) * (wt - mt); stv += (wt - mt) * (wv - mv); }
    ASSERT_TRUE(rate.has_value()) << "sample " << i;
    worst = std::max(worst, std::abs(*rate - stv / stt));
  }
  // dT/dt is up to 1.4e5 N·m/s here; agreement to 1e-3 N·m/s is 9 digits.
  EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace gc
