// Rows where the model jumps within the input sensors' noise (diagnosis/model_jumps.h): the paper's
// model on the NREL downwind coupling, a torque held next to one of its integer steps of teeth in
// contact and another held far from any, both logged with a transducer's white noise.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <optional>
#include <random>
#include <vector>

#include "diagnosis/model_jumps.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

constexpr double kZeta = 0.0124;         // [rad], 0.71 deg
constexpr double kBeta = -2.97;          // [rad]
constexpr double kTorqueNoise = 1000.0;  // [N·m], the transducer's
constexpr double kStep = 100.0;          // [N·m], the scan's

MeasurementSample at(double torque_nm) {
  MeasurementSample s;
  s.torque_nm = torque_nm;
  s.misalignment_rad = kZeta;
  s.direction_rad = kBeta;
  return s;
}

double moment(const CouplingModel& model, double torque_nm) {
  const SensorMoments m = model.predict(at(torque_nm)).moments;
  return std::hypot(m.y_nm, m.z_nm);
}

/// The first torque above `from` where the moment steps by more than 500 N·m in one scan step.
std::optional<double> first_jump(const CouplingModel& model, double from, double to) {
  for (double t = from; t < to; t += kStep) {
    if (std::abs(moment(model, t + kStep) - moment(model, t)) > 500.0) return t + 0.5 * kStep;
  }
  return std::nullopt;
}

/// 1,000 rows at 100 Hz holding `far`, then 1,000 holding `near`, torque logged with white noise
/// (`noise` N·m), moments the model's at the true torque.
std::vector<RecordedSample> two_holds(const CouplingModel& model, double far, double near, double noise) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal;
  std::vector<RecordedSample> out(2000);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double truth = i < 1000 ? far : near;
    out[i].input = at(truth + noise * normal(random));
    out[i].input.time_s = 0.01 * static_cast<double>(i);
    out[i].measured = model.predict(at(truth)).moments;
  }
  return out;
}

/// 0, 1, ..., n - 1: every row of a recording.
std::vector<std::size_t> all_rows(std::size_t n) {
  std::vector<std::size_t> rows(n);
  std::iota(rows.begin(), rows.end(), std::size_t{0});
  return rows;
}

TEST(ModelJumps, FindsTheHoldNextToAStepOfTeethInContactAndNotTheOneFarFromAny) {
  const CouplingModel model(testing::nrel_downwind(), {});
  const std::optional<double> jump = first_jump(model, 1.0e6, 1.3e6);
  ASSERT_TRUE(jump) << "the paper's model steps by a pair of teeth somewhere in 1.0-1.3 MN·m";
  // Far: a torque whose moment is smooth 10 noise deviations either side.
  double far = 0.6e6;
  while (first_jump(model, far - 10 * kTorqueNoise, far + 10 * kTorqueNoise)) far += 20 * kTorqueNoise;
  const std::vector<RecordedSample> rec = two_holds(model, far, *jump + 200.0, kTorqueNoise);
  const std::vector<std::size_t> rows = all_rows(rec.size());
  EXPECT_NEAR(input_noise_sigma(rec, rows, [](const MeasurementSample& s) { return s.torque_nm; }), kTorqueNoise,
              0.15 * kTorqueNoise);
  const std::optional<DataQualityFinding> f = rows_at_model_jumps(model, rec, rows, 1000.0, serial_for());
  ASSERT_TRUE(f);
  EXPECT_EQ(f->kind, DataQualityKind::model_jump);
  EXPECT_TRUE(f->excluded);
  std::size_t near_hold = 0, far_hold = 0;
  for (std::size_t r : f->rows) (r < 1000 ? far_hold : near_hold) += 1;
  // A row is found when its logged torque lies within two estimated deviations of the step: 94 %
  // of the hold at 0.2 deviations from it (the estimate a few per cent under the truth).
  EXPECT_GE(near_hold, 900u) << "the hold 200 N·m from the step, within the noise";
  EXPECT_LE(far_hold, 10u) << "the hold far from any step";
}

TEST(ModelJumps, InputsWithoutNoiseHaveNoRowsToLeaveOut) {
  const CouplingModel model(testing::nrel_downwind(), {});
  const std::optional<double> jump = first_jump(model, 1.0e6, 1.3e6);
  ASSERT_TRUE(jump);
  const std::vector<RecordedSample> rec = two_holds(model, 0.6e6, *jump + 200.0, 0.0);
  EXPECT_FALSE(rows_at_model_jumps(model, rec, all_rows(rec.size()), 1000.0, serial_for()));
}

TEST(ModelJumps, TheNoiseOfAnInputIsSeenPastAStaircase) {
  // Steps of 100 kN·m every 10 s pass the running median; white noise of 1 kN·m does not.
  std::mt19937_64 random(11);
  std::normal_distribution<double> normal;
  std::vector<RecordedSample> rec(6000);  // 60 s at 100 Hz
  for (std::size_t i = 0; i < rec.size(); ++i) {
    rec[i].input.time_s = 0.01 * static_cast<double>(i);
    rec[i].input.torque_nm = 1e6 + 1e5 * static_cast<double>(i / 1000) + 1000.0 * normal(random);
  }
  EXPECT_NEAR(input_noise_sigma(rec, all_rows(rec.size()), [](const MeasurementSample& s) { return s.torque_nm; }), 1000.0,
              150.0);
}

}  // namespace
}  // namespace gc
