// The monitor's per-test-cell logic without DDS (live/cell_monitor.h), the measurement's wire
// conversion and the test-cell name rule.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "analysis/recording_csv.h"
#include "codec/bundled_data.h"
#include "core/model_error.h"
#include "live/cell_monitor.h"
#include "live/live_names.h"
#include "live/measurement_wire.h"

namespace gc::live {
namespace {

const std::filesystem::path kRecording =
    GC_SOURCE_DIR "/data/recordings/paper_torque_ramp.csv";

CellModel paper() {
  return load_cell_model("paper", codec::bundled_data_dir("models"),
                         codec::bundled_data_dir("couplings"));
}

std::vector<RecordedSample> samples() { return analysis::read_recording(kRecording).samples; }


TEST(CellMonitor, EvaluatesEverySampleOfARunAndCountsItOnce) {
  CellMonitor monitor(paper(), {});
  const auto recording = samples();
  SensorMoments predicted;
  for (std::size_t i = 0; i < recording.size(); ++i) {
    ASSERT_EQ(monitor.take(7, i + 1, recording[i], "", predicted), SampleOutcome::evaluated);
  }
  const HealthReport health = monitor.health(std::chrono::system_clock::now());
  EXPECT_EQ(health.counts.taken, recording.size());
  EXPECT_EQ(health.counts.evaluated, recording.size());
  EXPECT_EQ(health.counts.lost, 0u);
  EXPECT_EQ(health.counts.runs, 1u);
  EXPECT_EQ(health.model.model_name, "paper");
  // paper_torque_ramp.csv is the paper's model plus 2 kN·m of noise (make_recordings.sh).
  EXPECT_TRUE(health.model.channels[0].at_noise_level);
  EXPECT_NEAR(health.model.channels[0].noise_nm, 2000.0, 300.0);
}

TEST(CellMonitor, CountsSequenceGapsAsLostAndRefusesWhatGoesBack) {
  CellMonitor monitor(paper(), {});
  const auto recording = samples();
  SensorMoments predicted;
  EXPECT_EQ(monitor.take(7, 5, recording[0], "", predicted), SampleOutcome::evaluated);
  EXPECT_EQ(monitor.take(7, 8, recording[1], "", predicted), SampleOutcome::evaluated);   // 6, 7 lost
  EXPECT_EQ(monitor.take(7, 8, recording[2], "", predicted), SampleOutcome::refused_out_of_order);
  EXPECT_EQ(monitor.take(7, 9, recording[0], "", predicted), SampleOutcome::refused_out_of_order);  // time back
  const HealthReport health = monitor.health(std::chrono::system_clock::now());
  EXPECT_EQ(health.counts.lost, 2u);    // samples before the first seen are not counted
  EXPECT_EQ(health.counts.refused_out_of_order, 2u);
  EXPECT_NE(health.last_refusal.find("measurement.time_s"), std::string::npos);
}

TEST(CellMonitor, ANewRunMayStartItsTimeAgain) {
  CellMonitor monitor(paper(), {});
  const auto recording = samples();
  SensorMoments predicted;
  for (std::uint64_t run : {1u, 2u}) {
    for (std::size_t i = 0; i < 100; ++i) {
      ASSERT_EQ(monitor.take(run, i + 1, recording[i], "", predicted), SampleOutcome::evaluated);
    }
  }
  const HealthReport health = monitor.health(std::chrono::system_clock::now());
  EXPECT_EQ(health.counts.runs, 2u);
  EXPECT_EQ(health.counts.evaluated, 200u);
  EXPECT_EQ(health.window_samples, 100u);   // the window restarts with the run
}

TEST(CellMonitor, RefusesNonFiniteAndModelRefusedSamplesWithTheirReason) {
  CellMonitor monitor(paper(), {});
  auto recording = samples();
  SensorMoments predicted;
  EXPECT_EQ(monitor.take(1, 1, std::nullopt, "measurement.torque_nm: nan", predicted),
            SampleOutcome::refused_not_finite);
  recording[1].input.misalignment_rad = 0.1;   // beyond the jam angle (0.016 rad)
  EXPECT_EQ(monitor.take(1, 2, recording[1], "", predicted), SampleOutcome::refused_by_model);
  const HealthReport health = monitor.health(std::chrono::system_clock::now());
  EXPECT_EQ(health.counts.refused_not_finite, 1u);
  EXPECT_EQ(health.counts.refused_by_model, 1u);
  EXPECT_EQ(health.counts.evaluated, 0u);
  EXPECT_NE(health.last_refusal.find("misalignment"), std::string::npos) << health.last_refusal;
}

TEST(CellMonitor, ASwapKeepsThePreviousModelsHealthAndRestartsTheWindow) {
  CellMonitor monitor(paper(), {});
  const auto recording = samples();
  SensorMoments predicted;
  for (std::size_t i = 0; i < 300; ++i) monitor.take(1, i + 1, recording[i], "", predicted);
  CellModel other = paper();
  other.name = "other";
  monitor.swap_model(other);
  for (std::size_t i = 300; i < 400; ++i) monitor.take(1, i + 1, recording[i], "", predicted);
  const HealthReport health = monitor.health(std::chrono::system_clock::now());
  EXPECT_EQ(health.model.model_name, "other");
  EXPECT_EQ(health.model.evaluated, 100u);
  ASSERT_TRUE(health.previous_model.has_value());
  EXPECT_EQ(health.previous_model->model_name, "paper");
  EXPECT_EQ(health.previous_model->evaluated, 300u);
  EXPECT_EQ(health.window_samples, 100u);
  EXPECT_EQ(health.counts.evaluated, 400u);
}

TEST(CellMonitor, HealthCoversHalfAWindowToAWindowOfMeasurementTime) {
  CellMonitorOptions options;
  options.window_s = 2.0;   // the recording: 100 samples a second
  CellMonitor monitor(paper(), options);
  const auto recording = samples();
  SensorMoments predicted;
  for (std::size_t i = 0; i < 1000; ++i) {
    monitor.take(1, i + 1, recording[i], "", predicted);
    const HealthReport health = monitor.health(std::chrono::system_clock::now());
    const double span = health.window_end_s - health.window_begin_s;
    if (recording[i].input.time_s >= 2.0) {
      ASSERT_GE(span, 0.99 - 1e-9) << "at t = " << recording[i].input.time_s;
      ASSERT_LT(span, 2.0);
    }
  }
}

TEST(MeasurementWire, CarriesSpeedAndTemperatureInSiAndRefusesNonFinite) {
  RecordedSample sample;
  sample.input.time_s = 1.0;
  sample.input.torque_nm = 1e6;
  sample.input.speed_rpm = 60.0;
  sample.input.temperature_c = 20.0;
  MeasurementOptionals optionals;
  gearcoupling_Measurement wire = to_wire(sample, 3, optionals);
  ASSERT_NE(wire.speed_rad_s, nullptr);
  EXPECT_NEAR(*wire.speed_rad_s, 2.0 * M_PI, 1e-12);   // 60 rpm = one turn a second
  EXPECT_NEAR(*wire.temperature_k, 293.15, 1e-12);
  EXPECT_EQ(wire.applied_my_nm, nullptr);
  const RecordedSample back = from_wire(wire);
  EXPECT_NEAR(*back.input.speed_rpm, 60.0, 1e-9);
  EXPECT_NEAR(*back.input.temperature_c, 20.0, 1e-9);
  wire.msz_nm = std::numeric_limits<double>::infinity();
  try {
    from_wire(wire);
    FAIL() << "an infinite moment was accepted";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "measurement.msz_nm");
  }
}

TEST(TestCellName, AcceptsNamesOfLettersDigitsDotsDashesUnderscoresOnly) {
  EXPECT_NO_THROW(require_test_cell_name("dyno-5MW_cell.2"));
  EXPECT_THROW(require_test_cell_name(""), InvalidInput);
  EXPECT_THROW(require_test_cell_name("cell 1"), InvalidInput);
  EXPECT_THROW(require_test_cell_name("\x01\xff"), InvalidInput);
  EXPECT_THROW(require_test_cell_name(std::string(65, 'a')), InvalidInput);
}

}  // namespace
}  // namespace gc::live
