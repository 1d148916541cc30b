// Issue 11 end to end: replay the bundled hidden-effect recording at 20x into the monitor; its
// health shows the error above the noise where validate names it; record captures the stream;
// diagnose on the capture names the effect and writes the model; the model is swapped in live;
// within one window the health is at the noise level. Every replayed sample is counted once.
#include <chrono>

#include "tests/live/sample_stream.h"

#include "tests/live/live_fixture.h"

namespace gc::test {
namespace {

using cli::testing::read_file;
using cli::testing::run_gearcoupling;
using cli::testing::temp_path;
using namespace std::chrono_literals;

constexpr std::uint64_t kRecordingSamples = 1000;   // rows of the bundled recording

TEST_F(LiveTest, ReplayMonitorRecordDiagnoseSwapBringsTheErrorToTheNoise) {
  const std::string cell = "e2e-cell";
  // A window longer than the recording (10 s of measurement time): the health then covers
  // what validate covers, so the two can be compared sentence for sentence.
  auto monitor = start_monitor({"--window-s", "20", "--health-period-s", "0.2", "--stale-s", "30",
                                "--dispose-s", "60"});
  const std::string capture = temp_path("capture") + ".csv";
  const std::string record_log = temp_path("record_log");
  ChildProcess record({GC_GEARCOUPLING_PATH, "record", "--test-cell", cell, "--seconds", "6",
                       "--out", capture, "--domain", std::to_string(test_domain())},
                      record_log);

  // 1. Replay at 20x, once the monitor and the recorder are both matched.
  const auto replay = run_gearcoupling(on_test_domain(
      {"replay", "--in", kHiddenEccentricity, "--test-cell", cell, "--speed", "20", "--readers",
       "2", "--wait-s", "20"}));
  ASSERT_EQ(replay.exit_code, 0) << replay.err;

  // 2. The health: every sample counted once, the error above the noise, at validate's region.
  const auto before = health_.wait_for(
      cell, [](const status::HealthView& h) { return h.taken >= kRecordingSamples; }, 20s);
  ASSERT_TRUE(before.has_value());
  EXPECT_EQ(before->taken, kRecordingSamples);
  EXPECT_EQ(before->evaluated, kRecordingSamples);
  EXPECT_EQ(before->lost, 0u);
  EXPECT_EQ(before->refused_not_finite + before->refused_by_model + before->refused_out_of_order, 0u);
  EXPECT_EQ(before->window_samples, kRecordingSamples);
  EXPECT_EQ(before->model_name, "paper");
  EXPECT_FALSE(before->at_noise_level[0]);
  EXPECT_GT(before->rmse_nm[0], 2.0 * before->noise_nm[0]);  // validate: 5.72 against 1.93 kN·m
  // The dashboard's badge: not green (issue 25: the cell once showed a green "alive" alone).
  EXPECT_NE(before->model_health, status::ModelHealth::at_noise_level);
  EXPECT_NE(before->model_health, status::ModelHealth::unknown);
  const auto validate = run_gearcoupling({"validate", "--data", kHiddenEccentricity, "--model", "paper"});
  ASSERT_EQ(validate.exit_code, 0) << validate.err;
  ASSERT_FALSE(before->worst_region.empty());
  EXPECT_NE(validate.out.find(before->worst_region), std::string::npos)
      << "health: " << before->worst_region << "\nvalidate:\n" << validate.out;

  // 3. The capture holds the stream, and diagnose on it names the effect.
  ASSERT_EQ(record.wait_exit(30.0), 0) << read_file(record_log);
  const auto validate_capture = run_gearcoupling({"validate", "--data", capture, "--model", "paper"});
  ASSERT_EQ(validate_capture.exit_code, 0) << validate_capture.err;
  EXPECT_NE(validate_capture.out.find("1000 rows"), std::string::npos) << validate_capture.out;
  const std::string fixed = temp_path("fixed") + ".textproto";
  const auto diagnose = run_gearcoupling(
      {"diagnose", "--data", capture, "--model", "paper", "--write-model", fixed});
  ASSERT_EQ(diagnose.exit_code, 0) << diagnose.err;
  EXPECT_NE(diagnose.out.find("explained by eccentricity"), std::string::npos) << diagnose.out;

  // 4. Swap the diagnosed model in.
  const auto swap = run_gearcoupling(on_test_domain(
      {"swap-model", "--test-cell", cell, "--model", fixed, "--wait-s", "20", "--operator", "tester"}));
  ASSERT_EQ(swap.exit_code, 0) << swap.err;
  EXPECT_NE(swap.out.find("model paper_diagnosed in force"), std::string::npos) << swap.out;
  const auto swapped = health_.wait_for(
      cell, [](const status::HealthView& h) { return h.model_name == "paper_diagnosed"; }, 10s);
  ASSERT_TRUE(swapped.has_value());
  ASSERT_EQ(swapped->model_name, "paper_diagnosed") << swapped->last_model_refusal;
  ASSERT_TRUE(swapped->previous_model_name.has_value());
  EXPECT_EQ(*swapped->previous_model_name, "paper");

  // 5. The test cell runs on (a new run: time starts again); within one window the error is
  // at the noise level.
  const auto again = run_gearcoupling(on_test_domain(
      {"replay", "--in", kHiddenEccentricity, "--test-cell", cell, "--speed", "20", "--wait-s", "20"}));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const auto after = health_.wait_for(
      cell, [](const status::HealthView& h) { return h.taken >= 2 * kRecordingSamples; }, 20s);
  ASSERT_TRUE(after.has_value());
  EXPECT_EQ(after->taken, 2 * kRecordingSamples);
  EXPECT_EQ(after->evaluated, 2 * kRecordingSamples);
  EXPECT_EQ(after->lost, 0u);
  EXPECT_EQ(after->runs, 2u);
  EXPECT_EQ(after->model_evaluated, kRecordingSamples);
  EXPECT_EQ(after->window_samples, kRecordingSamples);
  for (int channel = 0; channel < 2; ++channel) {
    EXPECT_TRUE(after->at_noise_level[channel]) << "channel " << channel << ": RMSE "
        << after->rmse_nm[channel] << " N·m, noise " << after->noise_nm[channel] << " N·m";
    EXPECT_LT(after->rmse_nm[channel], 1.2 * after->noise_nm[channel]);
    EXPECT_LT(after->rmse_nm[channel], 0.7 * after->previous_rmse_nm[channel]);  // 0.34, 0.51
  }
  EXPECT_EQ(after->worst_region, "");
  EXPECT_EQ(after->model_health, status::ModelHealth::at_noise_level);   // the badge turns green
}

// A model out of its effect's bounds is refused by swap-model before it is published (the
// monitor's own check of published text: robustness_test.cc, NanAndGarbage...).
TEST_F(LiveTest, SwapModelRefusesABadModelWithTheReasonAndKeepsTheModelInForce) {
  const std::string cell = "refuses";
  auto monitor = start_monitor({"--health-period-s", "0.1"});
  live::MeasurementPublisher publisher(participant_.get(), cell);
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  publish_stream(publisher, paper_samples(), 1, 1000.0);
  ASSERT_TRUE(health_.wait_for(cell, [](const status::HealthView& h) { return h.taken == 1; }, 10s));
  // Out of the effect's bounds: the monitor checks the text as validate --model checks a file.
  const std::string bad = temp_path("bad") + ".textproto";
  cli::testing::write_file(bad, "name: \"bad\" coupling: \"nrel_upwind\" effects { name: \"friction\" "
                                "parameters { name: \"mu0\" value: 7 } }\n");
  const auto swap = run_gearcoupling(on_test_domain({"swap-model", "--test-cell", cell, "--model", bad, "--operator", "tester"}));
  EXPECT_EQ(swap.exit_code, 2) << swap.out << swap.err;
  EXPECT_NE(swap.err.find("mu0"), std::string::npos) << swap.err;
  const auto health = health_.latest(cell);
  ASSERT_TRUE(health.has_value());
  EXPECT_EQ(health->model_name, "paper");
}

}  // namespace
}  // namespace gc::test
