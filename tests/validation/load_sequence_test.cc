// The load sequences follow the paper's test campaign (Section 6.3, Figures 10-14).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "core/model_error.h"
#include "diagnosis/synthesis/load_sequence.h"

namespace gc {
namespace {

constexpr double kJam = 0.0131;  // an arbitrary jam angle [rad]

LoadSequenceOptions options(LoadSequenceKind kind, int samples = 4000) {
  LoadSequenceOptions o;
  o.kind = kind;
  o.samples = samples;
  o.jam_angle_rad = kJam;
  return o;
}

// Signed misalignment fraction of the jam angle: negative when beta points the other way.
double signed_fraction(const MeasurementSample& s) {
  return s.misalignment_rad / kJam * (std::cos(s.direction_rad) >= 0.0 ? 1.0 : -1.0);
}

TEST(LoadSequence, MomentSweepSpansPlusMinusSixtyPercentOfJamAtFixedTorques) {
  const auto samples = load_sequence(options(LoadSequenceKind::moment_sweep));
  double lowest = 0.0, highest = 0.0;
  std::set<double> torques;
  for (const auto& s : samples) {
    lowest = std::min(lowest, signed_fraction(s));
    highest = std::max(highest, signed_fraction(s));
    torques.insert(s.torque_nm);
    // Negative misalignment is the same amplitude with the direction turned by pi (Figure 10).
    EXPECT_TRUE(std::abs(s.direction_rad) < 1e-12 ||
                std::abs(std::abs(s.direction_rad) - std::numbers::pi) < 1e-12);
  }
  EXPECT_NEAR(highest, 0.6, 1e-3);
  EXPECT_NEAR(lowest, -0.6, 1e-3);
  EXPECT_EQ(torques, (std::set<double>{0.3e6, 0.75e6, 1.5e6}));
}

TEST(LoadSequence, TorqueSweepRunsTenToNinetyFivePercentAtThirtyAndSixtyPercentOfJam) {
  const auto samples = load_sequence(options(LoadSequenceKind::torque_sweep));
  const auto [low, high] = std::minmax_element(samples.begin(), samples.end(),
      [](const auto& a, const auto& b) { return a.torque_nm < b.torque_nm; });
  EXPECT_NEAR(low->torque_nm, 0.10 * 1.5e6, 1.0);
  EXPECT_NEAR(high->torque_nm, 0.95 * 1.5e6, 0.002 * 1.5e6);
  std::set<long> fractions;
  for (const auto& s : samples) fractions.insert(std::lround(100 * signed_fraction(s)));
  EXPECT_EQ(fractions, (std::set<long>{-60, -30, 30, 60}));
}

TEST(LoadSequence, TorqueRampClimbsFromPointOneToTwoPointTwoMegaNewtonMetresInSeventeenSteps) {
  const auto samples = load_sequence(options(LoadSequenceKind::torque_ramp, 1700));
  std::set<double> torques;
  for (const auto& s : samples) torques.insert(s.torque_nm);
  ASSERT_EQ(torques.size(), 17u);
  EXPECT_NEAR(*torques.begin(), 0.1e6, 1e-6);
  EXPECT_NEAR(*torques.rbegin(), 2.2e6, 1e-3);
  EXPECT_TRUE(std::is_sorted(samples.begin(), samples.end(),
      [](const auto& a, const auto& b) { return a.torque_nm < b.torque_nm; }));
}

TEST(LoadSequence, TimeAdvancesBySamplePeriodFromZero) {
  auto o = options(LoadSequenceKind::torque_ramp, 10);
  o.sample_period_s = 0.5;
  const auto samples = load_sequence(o);
  for (std::size_t i = 0; i < samples.size(); ++i) EXPECT_DOUBLE_EQ(samples[i].time_s, 0.5 * i);
}

TEST(LoadSequence, RejectsTooFewSamplesNamingTheOption) {
  try {
    load_sequence(options(LoadSequenceKind::moment_sweep, 1));
    FAIL() << "one sample accepted";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "sequence.samples");
  }
}

TEST(LoadSequence, NamesRoundTrip) {
  for (auto kind : {LoadSequenceKind::moment_sweep, LoadSequenceKind::torque_sweep,
                    LoadSequenceKind::torque_ramp}) {
    EXPECT_EQ(load_sequence_kind(to_string(kind)), kind);
  }
  EXPECT_FALSE(load_sequence_kind("sweep"));
}

}  // namespace
}  // namespace gc
