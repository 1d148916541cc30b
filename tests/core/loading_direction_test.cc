// Issue 8, class 4: the "still" detector's dead band follows the recording's misalignment noise.
#include "core/loading_direction.h"

#include <gtest/gtest.h>

#include <vector>

#include "diagnosis/synthesis/synthesize.h"

namespace gc {
namespace {

struct Labelled {
  std::vector<MeasurementSample> samples;
  std::vector<int> truth;  // +1 ramp up, -1 ramp down, 0 hold
};

// Holds of 10 s and ramps of 6-10 s (0.75-1.25 mrad/s) between 2 and 12 mrad, every 0.05 s,
// plus white noise on the misalignment [rad].
Labelled holds_and_ramps(double noise_rad, std::uint64_t seed) {
  struct Segment { double from, to, seconds; };
  const Segment segments[] = {{0.002, 0.002, 10}, {0.002, 0.010, 8},  {0.010, 0.010, 10},
                              {0.010, 0.004, 6},  {0.004, 0.004, 10}, {0.004, 0.012, 8},
                              {0.012, 0.012, 10}, {0.012, 0.002, 10}, {0.002, 0.002, 10}};
  Labelled out;
  double t = 0.0;
  for (const Segment& s : segments) {
    const int n = static_cast<int>(s.seconds / 0.05 + 0.5);
    for (int i = 0; i < n; ++i) {
      MeasurementSample sample;
      sample.time_s = t;
      sample.misalignment_rad = s.from + (s.to - s.from) * i / n +
                                noise_rad * standard_normal(seed, out.samples.size(), 0);
      out.samples.push_back(sample);
      out.truth.push_back(s.to > s.from ? 1 : s.to < s.from ? -1 : 0);
      t += 0.05;
    }
  }
  return out;
}

// Share of the samples whose truth is `kind` (0: holds, else: ramps) labelled as the truth.
double share_right(const Labelled& l, bool holds) {
  int right = 0, total = 0;
  for (std::size_t i = 0; i < l.samples.size(); ++i) {
    if ((l.truth[i] == 0) != holds) continue;
    ++total;
    right += l.samples[i].loading_direction == l.truth[i] ? 1 : 0;
  }
  return static_cast<double>(right) / total;
}

TEST(LoadingDirection, DeadBandFollowsSixtyMicroradiansOfNoise) {
  // Issue 8: with 6e-5 rad of noise the fixed 2e-5 rad band labelled 143 of 836 still samples
  // still. Measured here (seeds 1-3): 92.7-95.8 % of hold samples still, 94.5-95.6 % of ramp
  // samples with their direction (seeds 1-10: 92.7-97.2 % and 94.1-95.9 %); the fixed band:
  // 0.1 % still, as every hold keeps crossing it.
  for (std::uint64_t seed : {1, 2, 3}) {
    Labelled l = holds_and_ramps(6e-5, seed);
    derive_loading_directions(l.samples);
    EXPECT_GT(share_right(l, true), 0.90) << seed;
    EXPECT_GT(share_right(l, false), 0.90) << seed;
    Labelled fixed = holds_and_ramps(6e-5, seed);
    LoadingDirectionTracker old(2e-5, 0.5);
    for (MeasurementSample& s : fixed.samples) {
      s.loading_direction = old.next(s.time_s, s.misalignment_rad);
    }
    EXPECT_LT(share_right(fixed, true), 0.05) << seed;
  }
}

TEST(LoadingDirection, DeadBandIsSixSigmaOfTheMisalignmentNoise) {
  Labelled l = holds_and_ramps(6e-5, 1);
  std::vector<double> amplitudes;
  for (const MeasurementSample& s : l.samples) amplitudes.push_back(s.misalignment_rad);
  EXPECT_NEAR(loading_dead_band_rad(amplitudes), 6.0 * 6e-5, 0.1 * 6.0 * 6e-5);
}

TEST(LoadingDirection, CleanRecordingsGetTheFloorAndKeepTheirLabels) {
  // Noise of 1e-7 rad: 6 sigma is below the 1e-6 rad floor. The ramps move 3.75e-5 rad a sample,
  // beyond both the floor and the 2e-5 rad band used before issue 22, so every label is the one
  // that band gave.
  Labelled l = holds_and_ramps(1e-7, 1);
  std::vector<double> amplitudes;
  for (const MeasurementSample& s : l.samples) amplitudes.push_back(s.misalignment_rad);
  EXPECT_EQ(loading_dead_band_rad(amplitudes), 1e-6);
  derive_loading_directions(l.samples);
  LoadingDirectionTracker old(2e-5, 0.5);
  for (const MeasurementSample& s : l.samples) {
    EXPECT_EQ(s.loading_direction, old.next(s.time_s, s.misalignment_rad)) << s.time_s;
  }
  EXPECT_GT(share_right(l, true), 0.95);
  EXPECT_GT(share_right(l, false), 0.95);
}

TEST(LoadingDirection, ACleanSlowSweepTurnsWithinASample) {
  // Issue 22: a noise-free sweep of 3e-6 rad a sample (10 Hz) up to 3 mrad and back. The turn is
  // labelled falling one sample after the peak; the 2e-5 rad band of before took 7 or 8.
  std::vector<MeasurementSample> samples;
  for (int i = 0; i <= 2000; ++i) {
    MeasurementSample s;
    s.time_s = 0.1 * i;
    s.misalignment_rad = 3e-6 * (i <= 1000 ? i : 2000 - i);
    samples.push_back(s);
  }
  auto first_fall = [](const std::vector<MeasurementSample>& labelled) {
    for (std::size_t i = 0; i < labelled.size(); ++i) if (labelled[i].travel_direction < 0) return static_cast<int>(i);
    return -1;
  };
  std::vector<MeasurementSample> derived = samples;
  derive_loading_directions(derived);
  EXPECT_EQ(first_fall(derived), 1001);
  EXPECT_EQ(derived[500].travel_direction, 1);
  std::vector<MeasurementSample> before = samples;
  LoadingDirectionTracker old(2e-5, 0.5);
  for (MeasurementSample& s : before) {
    s.loading_direction = old.next(s.time_s, s.misalignment_rad);
    s.travel_direction = old.last_travel();
  }
  EXPECT_GE(first_fall(before), 1007);
}

}  // namespace
}  // namespace gc
