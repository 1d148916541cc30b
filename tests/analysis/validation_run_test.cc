// validate's run (analysis/validation_run.h): a recording streamed in chunks, rows parsed and
// samples predicted on several threads, the statistics fed part by part on several threads,
// gives the numbers of the plain loop: the whole recording read, each sample predicted and
// added to one accumulator in file order.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "analysis/recording_csv.h"
#include "analysis/validation_run.h"
#include "core/model_error.h"
#include "run_process.h"
#include "test_models.h"

namespace gc::analysis {
namespace {

// Relative tolerance of the comparison: the parts keep the plain loop's order, so the bits
// agree today; a change that sums in another order (per-thread sums merged) may move the last
// digits, never the third.
constexpr double kRelative = 1e-12;

void expect_close(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, kRelative * std::max(1.0, std::abs(expected))) << what;
}

void expect_same(const ErrorAccumulator& actual, const ErrorAccumulator& expected, const std::string& what) {
  const ErrorMetrics a = actual.metrics(), e = expected.metrics();
  ASSERT_EQ(a.count, e.count) << what;
  expect_close(a.rmse_nm, e.rmse_nm, what + " rmse");
  expect_close(a.bias_nm, e.bias_nm, what + " bias");
  expect_close(a.max_abs_error_nm, e.max_abs_error_nm, what + " max");
  ASSERT_EQ(a.r_squared.has_value(), e.r_squared.has_value()) << what;
  if (a.r_squared) expect_close(*a.r_squared, *e.r_squared, what + " R^2");
}

void expect_same(const ChannelErrors& actual, const ChannelErrors& expected, const std::string& what) {
  expect_same(actual.y, expected.y, what + " y");
  expect_same(actual.z, expected.z, what + " z");
}

// A torque sweep over the misalignment range, some rows beyond the jam angle (the model refuses
// them), measured moments from a made-up law plus a wobble, one malformed row.
std::string sweep_recording(double jam_angle_rad) {
  std::string text = "time_s,torque_nm,misalignment_rad,direction_rad,msy_nm,msz_nm\n";
  for (int i = 0; i < 6000; ++i) {
    const double torque = 2e5 + 300.0 * i;
    const double misalignment = jam_angle_rad * (0.05 + 1.1 * (i % 600) / 600.0);
    text += i == 4321 ? "0.5,x,0,0,0,0\n"
                      : fmt::format("{},{},{},{},{},{}\n", 0.01 * i, torque, misalignment, 0.3,
                                    -0.1 * torque + 3e3 * std::sin(0.1 * i), 1e4 * std::cos(0.07 * i));
  }
  return text;
}

// The plain loop: the whole recording in memory, each sample predicted from all of it; `points`,
// when given, sampled as validate samples them.
ValidationAccumulator whole_recording_validation(const CouplingModel& model, const std::vector<RecordedSample>& samples,
                                                 const BinningOptions& binning, PointSampler* points = nullptr) {
  ValidationAccumulator expected(binning);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    try {
      const SensorMoments predicted = model.predict_at(std::span<const RecordedSample>(samples), i).moments;
      expected.add(samples[i], predicted);
      if (points) points->add(samples[i], predicted);
    } catch (const InvalidInput& error) {
      expected.reject(samples[i], error.field(), error.what());
      if (points) points->add(samples[i], std::nullopt);
    }
  }
  return expected;
}

TEST(ValidationRun, StreamedOnThreadsGivesTheNumbersOfThePlainLoop) {
  const codec::ModelFile model = gc::testing::bundled_model("paper");
  BinningOptions binning;
  binning.jam_angle_rad = model.model.geometry().jam_angle().angle_rad;
  const std::string path = cli::testing::temp_path("validation_run") + ".csv";
  cli::testing::write_file(path, sweep_recording(binning.jam_angle_rad));

  const Recording recording = read_recording(path);
  PointSampler expected_points(500);
  const ValidationAccumulator expected =
      whole_recording_validation(model.model, recording.samples, binning, &expected_points);

  for (const int threads : {1, 3}) {
    std::vector<ModelRun> runs;
    runs.push_back({"paper", &model.model, ValidationAccumulator(binning), PointSampler(500)});
    const RecordingSummary summary = run_validation(path, runs, {threads, 1000});
    const ValidationAccumulator& actual = runs[0].validation;
    const std::string on = fmt::format("{} threads", threads);
    EXPECT_EQ(summary.rows_read, 6000u);
    EXPECT_EQ(summary.excluded_rows, 1u);
    expect_same(actual.overall(), expected.overall(), on + ", overall");
    for (const Channel channel : kChannels) {
      expect_close(actual.noise_estimate_nm(channel), expected.noise_estimate_nm(channel), on + ", noise");
    }
    for (const BinDimension dimension : kBinDimensions) {
      const auto& bins = actual.binning(dimension).bins();
      const auto& expected_bins = expected.binning(dimension).bins();
      ASSERT_EQ(bins.size(), expected_bins.size()) << on;
      for (std::size_t b = 0; b < bins.size(); ++b) {
        expect_same(bins[b].errors, expected_bins[b].errors,
                    fmt::format("{}, {} bin {}", on, to_string(dimension), b));
      }
    }
    ASSERT_EQ(actual.map().cells.size(), expected.map().cells.size());
    for (std::size_t c = 0; c < actual.map().cells.size(); ++c) {
      expect_same(actual.map().cells[c], expected.map().cells[c], fmt::format("{}, map cell {}", on, c));
    }
    ASSERT_EQ(actual.rejections().size(), expected.rejections().size()) << on;
    EXPECT_GT(actual.rejected_count(), 100u);  // beyond the jam angle
    EXPECT_EQ(actual.rejected_count(), expected.rejected_count()) << on;
    ASSERT_EQ(runs[0].points.points().size(), expected_points.points().size()) << on;
    for (std::size_t p = 0; p < expected_points.points().size(); ++p) {
      EXPECT_EQ(runs[0].points.points()[p].recorded.input.time_s,
                expected_points.points()[p].recorded.input.time_s) << on;
    }
  }
}

// 100 Hz at 15 rpm (a revolution in 400 rows): a torque that swings, with a step every 7 s (a rig
// mode rings after each), a misalignment well inside the jam angle, moments from a made-up law.
std::string swinging_recording(int rows, double jam_angle_rad) {
  std::string text = "time_s,torque_nm,misalignment_rad,direction_rad,msy_nm,msz_nm,speed_rpm\n";
  for (int i = 0; i < rows; ++i) {
    const double t = 0.01 * i;
    const double torque = 1e6 + 4e5 * std::sin(2.0 * std::numbers::pi * t / 3.0) + 2e5 * ((i / 700) % 2);
    const double misalignment = jam_angle_rad * (0.3 + 0.2 * std::sin(2.0 * std::numbers::pi * t / 11.0));
    text += fmt::format("{},{},{},{},{},{},15\n", t, torque, misalignment, 0.3,
                        -0.1 * torque + 3e3 * std::sin(0.1 * i), 1e4 * std::cos(0.07 * i));
  }
  return text;
}

// Effects that read other samples of the recording than the one predicted (moment_delay's delay,
// before or after, and its average over a revolution; a formula's ringing mode, ~22 s of torque
// history) must see the recording as one pass does, whatever the chunks: 70,000 rows are three of
// validate's chunks of 32,768, and chunks of 1000 and 150 rows are shorter than the history read.
TEST(ValidationRun, EffectsThatReadOtherSamplesSeeAcrossChunks) {
  const codec::ModelFile paper = gc::testing::bundled_model("paper");
  BinningOptions binning;
  binning.jam_angle_rad = paper.model.geometry().jam_angle().angle_rad;
  const std::string path = cli::testing::temp_path("validation_run_history") + ".csv";
  cli::testing::write_file(path, swinging_recording(70000, binning.jam_angle_rad));
  const Recording recording = read_recording(path);
  ASSERT_EQ(recording.samples.size(), 70000u);

  const auto moment_delay = [](double delay_s, double revolutions) {
    return fmt::format("effects {{ name: \"moment_delay\" parameters {{ name: \"delay_s\" value: {} }} "
                       "parameters {{ name: \"averaging_revolutions\" value: {} }} }}\n", delay_s, revolutions);
  };
  const std::vector<std::pair<std::string, std::string>> effects = {
      {"delay 0.35 s, average over a revolution", moment_delay(0.35, 1.0)},
      {"delay -0.35 s (the moments lead)", moment_delay(-0.35, 0.0)},
      {"ringing at 2 Hz, zeta 0.05", "effects { name: \"expression\" parameters { name: "
                                       "\"ringing_2Hz_zeta0.05_on_y\" value: 0.3 } }\n"},
  };
  for (const auto& [what, extra] : effects) {
    const codec::ModelFile model = gc::testing::model_with("paper", extra);
    ASSERT_TRUE(model.model.reads_other_samples()) << what;
    const ValidationAccumulator expected = whole_recording_validation(model.model, recording.samples, binning);
    ASSERT_GT(expected.overall().y.metrics().count, 69000u) << what;
    for (const std::size_t chunk : {std::size_t{1} << 15, std::size_t{1000}, std::size_t{150}}) {
      std::vector<ModelRun> runs;
      runs.push_back({"with the effect", &model.model, ValidationAccumulator(binning), PointSampler(500)});
      run_validation(path, runs, {2, chunk});
      const std::string on = fmt::format("{}, chunks of {}", what, chunk);
      expect_same(runs[0].validation.overall(), expected.overall(), on);
      EXPECT_EQ(runs[0].validation.rejected_count(), expected.rejected_count()) << on;
    }
  }
}

// A reach that grows past everything held within one chunk (an average over a revolution when the
// speed falls from 15 to 0.5 rpm: 4 s, then 120 s) cannot be predicted as in one pass: a clear
// error, not numbers that depend on the chunks.
TEST(ValidationRun, AReachBeyondTheRowsHeldIsAnError) {
  const codec::ModelFile model = gc::testing::model_with(
      "paper", "effects { name: \"moment_delay\" parameters { name: \"averaging_revolutions\" value: 1 } }\n");
  std::string text = "time_s,torque_nm,misalignment_rad,direction_rad,msy_nm,msz_nm,speed_rpm\n";
  for (int i = 0; i < 3000; ++i) {
    text += fmt::format("{},1e6,0.001,0.3,-1e5,1e4,{}\n", 0.01 * i, i < 2000 ? 15.0 : 0.5);
  }
  const std::string path = cli::testing::temp_path("validation_run_reach") + ".csv";
  cli::testing::write_file(path, text);
  BinningOptions binning;
  binning.jam_angle_rad = model.model.geometry().jam_angle().angle_rad;
  std::vector<ModelRun> runs;
  runs.push_back({"paper + moment_delay", &model.model, ValidationAccumulator(binning), PointSampler()});
  // With 2 threads the next chunk is being read while the error is thrown: the read is waited for.
  for (const int threads : {1, 2}) {
    runs[0].validation = ValidationAccumulator(binning);
    try {
      run_validation(path, runs, {threads, 500});
      FAIL() << "no error, " << threads << " threads";
    } catch (const InvalidInput& error) {
      EXPECT_EQ(error.field(), "recording");
      EXPECT_NE(std::string(error.what()).find("for the sample at 20 s (120 s before it"), std::string::npos)
          << error.what();
    }
  }
  // Read in one chunk, the same recording validates.
  runs[0].validation = ValidationAccumulator(binning);
  EXPECT_NO_THROW(run_validation(path, runs, {1, 5000}));
}

}  // namespace
}  // namespace gc::analysis
