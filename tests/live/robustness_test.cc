// The monitor survives what a test cell does to it (issue 11): a test cell that stops, time
// going backwards, NaN and garbage, a model swap every 100 ms, a restart of the service or of
// the monitor itself.
#include <signal.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>

#include "gearcoupling.h"
#include "live/live_qos.h"
#include "live/model_swap_publisher.h"
#include "tests/live/live_fixture.h"
#include "tests/live/sample_stream.h"

namespace gc::test {
namespace {

using namespace std::chrono_literals;
using cli::testing::read_file;
using status::HealthView;

const std::string kPaperText = read_file(GC_SOURCE_DIR "/data/models/paper.textproto");

std::string variant_text(const std::string& name, double mu0) {
  return "name: \"" + name + "\"\ncoupling: \"nrel_upwind\"\n"
         "effects { name: \"friction\" parameters { name: \"mu0\" value: " + std::to_string(mu0) +
         " } }\neffects { name: \"pressure_angle_rotation\" }\neffects { name: \"self_weight\" }\n";
}

TEST_F(LiveTest, AStoppedTestCellGoesStaleThenIsDisposed) {
  auto monitor = start_monitor({"--health-period-s", "0.1", "--stale-s", "0.5", "--dispose-s", "1.5"});
  live::MeasurementPublisher publisher(participant_.get(), "stops");
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  publish_stream(publisher, paper_samples(), 200, 2000.0);
  const auto live = health_.wait_for("stops", [](const HealthView& h) { return h.taken == 200; }, 10s);
  ASSERT_TRUE(live.has_value());
  const auto stale = health_.wait_for("stops", [](const HealthView& h) { return h.stale; }, 10s);
  ASSERT_TRUE(stale && stale->stale);
  EXPECT_EQ(stale->evaluated, 200u);
  const auto gone = health_.wait_for("stops", [](const HealthView& h) { return h.disposed; }, 10s);
  ASSERT_TRUE(gone && gone->disposed);
  // It comes back as a new test cell, counted from zero.
  publish_stream(publisher, paper_samples(), 50, 2000.0, 200);
  const auto back = health_.wait_for(
      "stops", [](const HealthView& h) { return !h.disposed && h.taken == 50; }, 10s);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->taken, 50u);
  EXPECT_TRUE(monitor->running());
}

TEST_F(LiveTest, TimeGoingBackwardsIsRefusedWithinARunAndAcceptedFromANewRun) {
  auto monitor = start_monitor({"--health-period-s", "0.1"});
  const auto samples = paper_samples();
  {
    live::MeasurementPublisher first(participant_.get(), "backwards");
    ASSERT_TRUE(first.wait_for_readers(1, 10s));
    publish_stream(first, samples, 100, 5000.0);
    RecordedSample earlier = samples[10];       // t = 0.1 s after t = 0.99 s
    first.add(earlier);
    first.flush();
  }
  // A replay restarted: a new run whose time starts at 0 again.
  live::MeasurementPublisher second(participant_.get(), "backwards");
  ASSERT_TRUE(second.wait_for_readers(1, 10s));
  publish_stream(second, samples, 100, 5000.0);
  const auto health = health_.wait_for(
      "backwards", [](const HealthView& h) { return h.taken == 201; }, 10s);
  ASSERT_TRUE(health.has_value());
  EXPECT_EQ(health->taken, 201u);
  EXPECT_EQ(health->refused_out_of_order, 1u);
  EXPECT_EQ(health->evaluated, 200u);
  EXPECT_EQ(health->runs, 2u);
  EXPECT_EQ(health->lost, 0u);
}

TEST_F(LiveTest, NanAndGarbageAreCountedAndRefusedAndTheMonitorServesOn) {
  auto monitor = start_monitor({"--health-period-s", "0.1"});
  auto samples = paper_samples();
  live::MeasurementPublisher publisher(participant_.get(), "garbage");
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<RecordedSample> sent(samples.begin(), samples.begin() + 20);
  sent[3].input.torque_nm = nan;
  sent[4].measured.y_nm = std::numeric_limits<double>::infinity();
  sent[5].input.speed_rpm = nan;
  sent[6].input.misalignment_rad = 0.5;    // beyond the jam angle
  sent[7].input.torque_nm = -1e6;          // not a physical torque
  for (const RecordedSample& sample : sent) publisher.add(sample);
  publisher.flush();

  // Text garbage where a test cell name goes: refused, logged, no health for it.
  protocol::Entity publisher_entity = live::make_live_publisher(participant_.get());
  protocol::Entity topic = live::make_measurement_topic(participant_.get());
  const protocol::Qos qos = live::measurement_writer_qos();
  protocol::Entity writer(dds_create_writer(publisher_entity.get(), topic.get(), qos.get(), nullptr));
  gearcoupling_MeasurementBatch garbage{};
  std::strcpy(garbage.test_cell, "\x01\x7f garbage; DROP TABLE\xff");
  garbage.run_id = 1;
  gearcoupling_Measurement one{};
  one.sequence_number = 1;
  garbage.samples._buffer = &one;
  garbage.samples._length = garbage.samples._maximum = 1;
  ASSERT_EQ(dds_write(writer.get(), &garbage), DDS_RETCODE_OK);

  // A model that is no model, and one with an unknown effect: refused with the reason.
  live::ModelSwapPublisher swaps(participant_.get(), {"garbage"});
  ASSERT_TRUE(swaps.wait_for_readers(1, 10s));
  swaps.publish("garbage", "\x01\x02 not { a model");
  auto refused = health_.wait_for(
      "garbage", [](const HealthView& h) { return !h.last_model_refusal.empty(); }, 10s);
  ASSERT_TRUE(refused.has_value());
  EXPECT_FALSE(refused->last_model_refusal.empty());
  swaps.publish("garbage", "name: \"x\" coupling: \"nrel_upwind\" effects { name: \"warp_drive\" }");
  refused = health_.wait_for(
      "garbage", [](const HealthView& h) { return h.last_model_refusal.find("warp_drive") != std::string::npos; }, 10s);
  ASSERT_TRUE(refused.has_value());
  EXPECT_NE(refused->last_model_refusal.find("warp_drive"), std::string::npos) << refused->last_model_refusal;
  EXPECT_EQ(refused->model_name, "paper");

  publish_stream(publisher, samples, 10, 5000.0, 20);
  const auto health = health_.wait_for("garbage", [](const HealthView& h) { return h.taken == 30; }, 10s);
  ASSERT_TRUE(health.has_value());
  EXPECT_EQ(health->taken, 30u);
  EXPECT_EQ(health->refused_not_finite, 3u);
  EXPECT_EQ(health->refused_by_model, 2u);
  EXPECT_EQ(health->evaluated, 25u);
  EXPECT_EQ(health->lost, 0u);
  EXPECT_TRUE(monitor->running());
}

// The issue asks for a minute; 10 s (100 swaps, 20,000 samples) in the suite keeps it short.
// bench/ runs the full minute (docs/benchmarks.md).
TEST_F(LiveTest, AModelSwapEvery100MsLosesNoSampleAndEvaluatesNoneTwice) {
  auto monitor = start_monitor({"--health-period-s", "0.2"});
  live::MeasurementPublisher publisher(participant_.get(), "swaps");
  live::ModelSwapPublisher swaps(participant_.get(), {"swaps"});
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  ASSERT_TRUE(swaps.wait_for_readers(1, 10s));
  std::atomic<bool> streaming{true};
  std::thread swapper([&] {
    for (int i = 0; streaming && i < 200; ++i) {
      swaps.publish("swaps", i % 2 == 0 ? variant_text("mu012", 0.12) : kPaperText);
      std::this_thread::sleep_for(100ms);
    }
  });
  const std::uint64_t published = publish_stream(publisher, paper_samples(), 20000, 2000.0);
  streaming = false;
  swapper.join();
  const auto health = health_.wait_for(
      "swaps", [&](const HealthView& h) { return h.taken >= published; }, 20s);
  ASSERT_TRUE(health.has_value());
  EXPECT_EQ(health->taken, published);
  EXPECT_EQ(health->evaluated, published);
  EXPECT_EQ(health->lost, 0u);
  EXPECT_EQ(health->refused_out_of_order, 0u);
  ASSERT_TRUE(health->previous_model_name.has_value());
  EXPECT_NE(*health->previous_model_name, health->model_name);
  EXPECT_EQ(health->last_model_refusal, "");
  EXPECT_TRUE(monitor->running());
}

TEST_F(LiveTest, ARestartedMonitorResumesWithTheLatestModelSwap) {
  live::MeasurementPublisher publisher(participant_.get(), "restart");
  live::ModelSwapPublisher swaps(participant_.get(), {"restart"});
  auto first = start_monitor({"--health-period-s", "0.1"});
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  swaps.publish("restart", variant_text("mu012", 0.12));
  publish_stream(publisher, paper_samples(), 300, 2000.0);
  ASSERT_TRUE(health_.wait_for("restart", [](const HealthView& h) { return h.taken == 300; }, 10s));
  first->signal(SIGKILL);

  auto second = start_monitor({"--health-period-s", "0.1"});
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  // The swap is TRANSIENT_LOCAL: the new monitor reads it before the stream goes on.
  std::this_thread::sleep_for(300ms);
  publish_stream(publisher, paper_samples(), 300, 2000.0, 300);
  const auto health = health_.wait_for(
      "restart", [](const HealthView& h) { return h.taken == 300 && h.model_name == "mu012"; }, 10s);
  ASSERT_TRUE(health.has_value());
  EXPECT_EQ(health->model_name, "mu012");
  EXPECT_EQ(health->taken, 300u);
  EXPECT_EQ(health->evaluated, 300u);
  EXPECT_EQ(health->lost, 0u);   // counted from the first sample it saw
}

TEST_F(LiveTest, TheMonitorDoesNotDependOnTheServiceRestarting) {
  auto service = std::make_unique<ServiceProcess>();
  auto monitor = start_monitor({"--health-period-s", "0.1"});
  live::MeasurementPublisher publisher(participant_.get(), "service");
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  publish_stream(publisher, paper_samples(), 200, 2000.0);
  service->signal(SIGKILL);
  publish_stream(publisher, paper_samples(), 200, 2000.0, 200);
  service = std::make_unique<ServiceProcess>();
  publish_stream(publisher, paper_samples(), 200, 2000.0, 400);
  const auto health = health_.wait_for("service", [](const HealthView& h) { return h.taken == 600; }, 10s);
  ASSERT_TRUE(health.has_value());
  EXPECT_EQ(health->evaluated, 600u);
  EXPECT_EQ(health->lost, 0u);
}

TEST(Monitor, RefusesABadFlagOrModelWithExitTwoAndTheReason) {
  std::string log;
  auto bad_window = start_monitor({"--window-s", "-1"}, &log);
  EXPECT_EQ(bad_window->wait_exit(20.0), 2);
  EXPECT_NE(read_file(log).find("--window-s"), std::string::npos) << read_file(log);
  const std::string model = cli::testing::temp_path("bad_model") + ".textproto";
  cli::testing::write_file(model, "name: \"bad\" coupling: \"nrel_upwind\" effects { name: \"friction\" "
                                  "parameters { name: \"mu0\" value: 7 } }\n");
  auto bad_model = start_monitor({"--cell", "c1=" + model}, &log);
  EXPECT_EQ(bad_model->wait_exit(20.0), 2);
  EXPECT_NE(read_file(log).find("mu0"), std::string::npos) << read_file(log);
}

}  // namespace
}  // namespace gc::test
