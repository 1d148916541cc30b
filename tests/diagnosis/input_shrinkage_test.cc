// The inputs read back toward their centred means (diagnosis/input_shrinkage.h): the window is
// centred and runs over the listed rows only, keep 1 changes nothing, a direction is averaged
// as a unit vector across +-pi, and a median keeps a staircase and a ramp that a mean smears.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "diagnosis/input_shrinkage.h"

namespace gc {
namespace {

std::vector<RecordedSample> ramp(std::size_t count) {
  std::vector<RecordedSample> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    out[i].input.time_s = 0.1 * static_cast<double>(i);
    out[i].input.torque_nm = 1e5 * static_cast<double>(i * i);  // a parabola: its centred mean is above it
    out[i].input.misalignment_rad = 1e-3;
    out[i].input.direction_rad = 0.5;
  }
  return out;
}

TEST(InputShrinkage, KeepingNoneGivesTheCentredMeanOverTheListedRows) {
  const std::vector<RecordedSample> r = ramp(10);
  const std::vector<std::size_t> rows = {0, 1, 2, 3, 5, 6, 7, 8, 9};  // row 4 excluded
  InputShrinks s;
  s.torque = {0.25, 0.0};  // +-0.125 s: the row itself and its listed neighbours 0.1 s away
  const std::vector<RecordedSample> out = with_shrunk_inputs(r, rows, s);
  EXPECT_NEAR(out[2].input.torque_nm, 1e5 * (1.0 + 4.0 + 9.0) / 3.0, 1e-6);
  EXPECT_EQ(out[3].input.torque_nm, r[3].input.torque_nm)
      << "row 4 is not listed: it feeds no mean, and row 3's window keeps as many rows either side (none)";
  EXPECT_EQ(out[4].input.torque_nm, r[4].input.torque_nm) << "and receives none";
  EXPECT_EQ(out[0].input.torque_nm, r[0].input.torque_nm)
      << "the first row's window is cut at the start on both sides, so it stays centred: the row alone";
  EXPECT_EQ(out[6].input.misalignment_rad, r[6].input.misalignment_rad);
  EXPECT_EQ(out[6].input.time_s, r[6].input.time_s);
}

TEST(InputShrinkage, KeepingHalfIsHalfwayAndKeepingAllChangesNothing) {
  const std::vector<RecordedSample> r = ramp(10);
  const std::vector<std::size_t> rows = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  InputShrinks half;
  half.torque = {0.25, 0.5};
  const double mean = 1e5 * (16.0 + 25.0 + 36.0) / 3.0;
  EXPECT_NEAR(with_shrunk_inputs(r, rows, half)[5].input.torque_nm, 0.5 * (mean + 25e5), 1e-6);
  InputShrinks all;
  all.torque = {4.0, 1.0};
  EXPECT_TRUE(all.none());
  EXPECT_EQ(with_shrunk_inputs(r, rows, all)[5].input.torque_nm, r[5].input.torque_nm);
}

TEST(InputShrinkage, ADirectionIsAveragedAcrossPlusMinusPi) {
  std::vector<RecordedSample> r = ramp(3);
  r[0].input.direction_rad = std::numbers::pi - 0.1;
  r[1].input.direction_rad = -std::numbers::pi + 0.1;
  r[2].input.direction_rad = std::numbers::pi - 0.1;
  InputShrinks s;
  s.direction = {0.25, 0.0};
  const std::vector<RecordedSample> out = with_shrunk_inputs(r, std::vector<std::size_t>{0, 1, 2}, s);
  // The mean of the three unit vectors points at pi - 0.1/3, not near 0.
  EXPECT_NEAR(std::remainder(out[1].input.direction_rad - (std::numbers::pi - 0.1 / 3.0), 2.0 * std::numbers::pi), 0.0,
              2e-3);
}

// A search reads one trial after another through one shrinker: each trial's inputs are a fresh
// with_shrunk_inputs' to the bit, whatever the trial before left, on every row or on those read.
TEST(InputShrinkage, AShrinkerGivesEachTrialAsAFreshReadBack) {
  std::vector<RecordedSample> r = ramp(40);
  for (std::size_t i = 0; i < r.size(); ++i) {
    r[i].input.misalignment_rad = 1e-3 * std::sin(0.3 * static_cast<double>(i));
    r[i].input.direction_rad = std::numbers::pi - 0.05 * static_cast<double>(i % 5);
  }
  const std::vector<std::size_t> rows = {0, 1, 2, 3, 5, 6, 7, 8, 9, 10, 12, 20, 21, 22, 30, 31, 39};
  const std::vector<std::size_t> read = {2, 3, 4, 21, 39};  // 4 is not listed: as recorded
  InputShrinks torque, both, direction, median;
  torque.torque = {0.25, 0.0};
  median.torque = {1.0, 0.0, true};
  median.misalignment = {1.0, 0.5, true};
  both.torque = {1.0, 0.5};
  both.misalignment = {0.25, 0.0};
  direction.direction = {1.0, 0.5};
  InputShrinker shrinker(r, rows);
  for (const InputShrinks& trial : {torque, both, median, direction, InputShrinks{}, both, median}) {
    const std::vector<RecordedSample> fresh = with_shrunk_inputs(r, rows, trial);
    const std::span<const RecordedSample> all = shrinker.shrunk(trial);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      differing += all[i].input.torque_nm != fresh[i].input.torque_nm ||
                   all[i].input.misalignment_rad != fresh[i].input.misalignment_rad ||
                   all[i].input.direction_rad != fresh[i].input.direction_rad;
    }
    EXPECT_EQ(differing, 0u);
    shrinker.shrunk(direction, read);  // another trial in between, on the rows read
    const std::span<const RecordedSample> again = shrinker.shrunk(trial, read);
    differing = 0;
    for (const std::size_t i : read) {
      differing += again[i].input.torque_nm != fresh[i].input.torque_nm ||
                   again[i].input.misalignment_rad != fresh[i].input.misalignment_rad ||
                   again[i].input.direction_rad != fresh[i].input.direction_rad;
    }
    EXPECT_EQ(differing, 0u);
  }
}

TEST(InputShrinkage, AMedianKeepsAStaircaseAndARampWhereAMeanSmearsThem) {
  // 1 s stairs of 100 kN·m, then a ramp of 50 kN·m/s, at 100 Hz, with 1 kN·m of white noise; the
  // window (2 s) spans a whole stair and the step after it.
  std::mt19937_64 random(3);
  std::normal_distribution<double> normal;
  std::vector<RecordedSample> r(1000);
  std::vector<double> truth(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double t = 0.01 * static_cast<double>(i);
    truth[i] = i < 500 ? 1e6 + 1e5 * std::floor(t) : 1.5e6 + 5e4 * (t - 5.0);
    r[i].input.time_s = t;
    r[i].input.torque_nm = truth[i] + 1000.0 * normal(random);
  }
  std::vector<std::size_t> rows(r.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
  InputShrinks median, mean;
  median.torque = {2.0, 0.0, true};
  mean.torque = {2.0, 0.0, false};
  const std::vector<RecordedSample> by_median = with_shrunk_inputs(r, rows, median);
  const std::vector<RecordedSample> by_mean = with_shrunk_inputs(r, rows, mean);
  double worst_median = 0.0, worst_mean = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    worst_median = std::max(worst_median, std::abs(by_median[i].input.torque_nm - truth[i]));
    worst_mean = std::max(worst_mean, std::abs(by_mean[i].input.torque_nm - truth[i]));
  }
  EXPECT_LT(worst_median, 5000.0) << "the median is off by a few noise deviations at most, at the steps";
  EXPECT_GT(worst_mean, 4e4) << "a mean over a step is off by a good share of the step";
}

TEST(InputShrinkage, CentredMediansAreTheMedianReadBacksCentres) {
  std::vector<RecordedSample> r = ramp(40);
  for (std::size_t i = 0; i < r.size(); ++i) r[i].input.torque_nm += (i % 3 == 0 ? 4e5 : -2e5);
  const std::vector<std::size_t> rows = {0, 1, 2, 3, 5, 6, 7, 8, 9, 10, 12, 20, 21, 22, 30, 31, 39};
  const std::vector<std::size_t> at = {2, 7, 21, 31};
  InputShrinks median;
  median.torque = {0.5, 0.0, true};
  const std::vector<RecordedSample> read_back = with_shrunk_inputs(r, rows, median, at);
  const std::vector<double> centres =
      centred_medians(r, rows, 0.5, at, [](const MeasurementSample& s) { return s.torque_nm; });
  ASSERT_EQ(centres.size(), at.size());
  for (std::size_t j = 0; j < at.size(); ++j) EXPECT_EQ(centres[j], read_back[at[j]].input.torque_nm) << at[j];
}

TEST(InputShrinkage, OnlyTheRowsAskedForAreReadBack) {
  const std::vector<RecordedSample> r = ramp(10);
  const std::vector<std::size_t> rows = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  InputShrinks s;
  s.torque = {0.25, 0.0};
  const std::vector<std::size_t> at = {3, 7};
  const std::vector<RecordedSample> some = with_shrunk_inputs(r, rows, s, at);
  const std::vector<RecordedSample> all = with_shrunk_inputs(r, rows, s);
  EXPECT_EQ(some[3].input.torque_nm, all[3].input.torque_nm);
  EXPECT_EQ(some[7].input.torque_nm, all[7].input.torque_nm);
  EXPECT_EQ(some[5].input.torque_nm, r[5].input.torque_nm) << "not asked for: as recorded";
}

}  // namespace
}  // namespace gc
