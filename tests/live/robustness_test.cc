// The monitor survives what a test cell does to it (issue 11): a test cell that stops, time
// going backwards, NaN and garbage, a model swap every 100 ms, a restart of the service or of
// the monitor itself, with its audit trail on disk (whole, or damaged).
#include <signal.h>

#include <atomic>
#include <filesystem>
#include <cmath>
#include <cstring>
#include <limits>
#include <thread>

#include "gearcoupling.h"
#include "live/live_qos.h"
#include "live/model_swap_publisher.h"
#include "live/swap_audit_file.h"
#include "tests/live/live_fixture.h"
#include "tests/live/live_status.h"
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
  std::uint64_t published = 0;
  {
    // A jthread: a failed write below is reported as the test's failure, not an abort.
    std::jthread swapper([&](std::stop_token stop) {
      for (int i = 0; !stop.stop_requested() && i < 200; ++i) {
        swaps.publish("swaps", i % 2 == 0 ? variant_text("mu012", 0.12) : kPaperText);
        std::this_thread::sleep_for(100ms);
      }
    });
    published = publish_stream(publisher, paper_samples(), 20000, 2000.0);
  }
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

// A monitor that stops acknowledging (here SIGSTOP, in a test cell a host busy for a second or two)
// makes each dds_write wait its 1 s and time out. The DAQ's publisher waits on, up to its
// patience: the stream is delayed, not lost, and nothing is evaluated twice. Beyond its patience
// flush() throws, names the wait and keeps the batch for the next flush.
TEST_F(LiveTest, AMonitorThatStopsAcknowledgingDelaysTheStreamAndLosesNothing) {
  auto monitor = start_monitor({"--health-period-s", "0.1"});
  live::MeasurementPublisher publisher(participant_.get(), "stalled");
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  publish_stream(publisher, paper_samples(), 100, 5000.0);
  ASSERT_TRUE(health_.wait_for("stalled", [](const HealthView& h) { return h.taken == 100; }, 10s));

  // Full batches until the writer's unacknowledged window (WhcHigh, 500 kB) is full: then a
  // write blocks. 2 s of silence is longer than one dds_write waits, and 1 s inside the
  // participants' lease (3 s, cyclonedds-loopback.xml), beyond which the monitor would be
  // unmatched as any dead reader.
  const auto samples = paper_samples();
  monitor->signal(SIGSTOP);
  std::jthread resume([&] {
    std::this_thread::sleep_for(2000ms);
    monitor->signal(SIGCONT);
  });
  const std::uint64_t streamed = 100 + publish_stream(publisher, samples, 40000, 1e9, 100);
  resume.join();
  EXPECT_GT(publisher.retried_writes(), 0u) << "the monitor's silence never blocked a write";

  // Now with 0.3 s of patience (one write of 1 s) against 2 s of silence: an error, the batch
  // kept, and a second of margin for the window to fill on a busy host.
  publisher.set_patience(300ms);
  monitor->signal(SIGSTOP);
  std::jthread resume_later([&] {
    std::this_thread::sleep_for(2000ms);
    monitor->signal(SIGCONT);
  });
  std::string error;
  try {
    publish_stream(publisher, samples, 40000, 1e9, streamed);
  } catch (const protocol::DdsError& e) {
    error = e.what();
  }
  ASSERT_NE(error.find("kept queued"), std::string::npos) << "no error, or not this one: " << error;
  EXPECT_NE(error.find("stalled"), std::string::npos) << error;
  publisher.set_patience(30s);
  publisher.flush();   // waits for the monitor to go on
  resume_later.join();
  const std::uint64_t written = publisher.samples_written();

  const auto health = health_.wait_for(
      "stalled", [&](const HealthView& h) { return h.taken >= written; }, 30s);
  ASSERT_TRUE(health.has_value());
  EXPECT_EQ(health->taken, written);
  EXPECT_EQ(health->evaluated, written);
  EXPECT_EQ(health->lost, 0u);
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

/// A new empty directory for a monitor's --state-dir.
std::string new_state_dir() {
  const std::string dir = cli::testing::temp_path("state");
  std::filesystem::create_directories(dir);
  return dir;
}

/// Starts a monitor with `args` into `monitor`, publishes 300 samples of `test_cell` and swaps
/// its model to paper_downwind with `gearcoupling swap-model`, as an operator would.
void start_monitor_and_swap(status::CellBoard& health, live::MeasurementPublisher& publisher,
                            const std::vector<std::string>& args, const std::string& test_cell,
                            std::unique_ptr<ChildProcess>& monitor) {
  monitor = start_monitor(args);
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  publish_stream(publisher, paper_samples(), 300, 2000.0);
  ASSERT_TRUE(health.wait_for(test_cell, [](const HealthView& h) { return h.taken == 300; }, 10s));
  const auto swap = cli::testing::run_gearcoupling(on_test_domain(
      {"swap-model", "--test-cell", test_cell, "--model", "paper_downwind", "--wait-s", "10",
       "--operator", "tester"}));
  ASSERT_EQ(swap.exit_code, 0) << swap.err;
}

// Issue 25's leftover: with --state-dir the audit trail outlives the monitor. Two swaps (the
// CLI's, and a writer of the test's that stays alive), a SIGKILL, a new monitor on the same
// directory: its status shows both swaps; the live writer's swap, which the new monitor gets
// again (TRANSIENT_LOCAL) and puts in force again, is not audited a second time.
TEST_F(LiveTest, TheAuditTrailOutlivesAKilledMonitor) {
  const std::vector<std::string> args = {"--health-period-s", "0.1", "--state-dir", new_state_dir()};
  live::MeasurementPublisher publisher(participant_.get(), "audited");
  std::unique_ptr<ChildProcess> first;
  ASSERT_NO_FATAL_FAILURE(start_monitor_and_swap(health_, publisher, args, "audited", first));
  live::ModelSwapPublisher swaps(participant_.get(), {"audited"}, "by=tester@bench;source=file mu012.textproto");
  ASSERT_TRUE(swaps.wait_for_readers(1, 10s));
  swaps.publish("audited", variant_text("mu012", 0.12));
  const v1::LiveStatus before = wait_for_status(
      [](const v1::LiveStatus& s) { return s.monitors(0).swaps() == 2; });
  ASSERT_EQ(before.monitors_size(), 1);
  ASSERT_EQ(before.monitors(0).recent_swaps_size(), 2);
  const std::string killed = before.monitors(0).monitor_id();
  first->signal(SIGKILL);
  ASSERT_EQ(first->wait_exit(10.0), 128 + SIGKILL);

  auto second = start_monitor(args);
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  std::this_thread::sleep_for(300ms);   // the live writer's swap reaches the new monitor first
  publish_stream(publisher, paper_samples(), 300, 2000.0, 300);
  const v1::LiveStatus after = wait_for_status([&](const v1::LiveStatus& s) {
    return s.monitors(0).monitor_id() != killed && s.test_cells_size() == 1 &&
           s.test_cells(0).model().model_name() == "mu012";
  });
  ASSERT_EQ(after.monitors_size(), 1);
  ASSERT_EQ(after.test_cells_size(), 1);
  EXPECT_EQ(after.test_cells(0).model().model_name(), "mu012");   // the live writer's, again
  const v1::MonitorRecord& m = after.monitors(0);
  EXPECT_EQ(m.swaps(), 0u);   // none taken by this monitor: the trail is the killed one's
  ASSERT_EQ(m.recent_swaps_size(), 2);
  for (int i = 0; i < 2; ++i) {
    const v1::SwapAuditRecord& was = before.monitors(0).recent_swaps(i);
    const v1::SwapAuditRecord& is = m.recent_swaps(i);
    EXPECT_EQ(is.test_cell(), "audited");
    EXPECT_EQ(is.by(), was.by());
    EXPECT_EQ(is.source(), was.source());
    EXPECT_EQ(is.model_before(), was.model_before());
    EXPECT_EQ(is.model_after(), was.model_after());
    EXPECT_DOUBLE_EQ(is.at_unix_s(), was.at_unix_s());
    EXPECT_DOUBLE_EQ(is.before_msy_rmse_nm(), was.before_msy_rmse_nm());
  }
  EXPECT_EQ(m.recent_swaps(0).by(), "tester");   // the CLI's --operator (start_monitor_and_swap)
  EXPECT_EQ(m.recent_swaps(0).model_after(), "paper_downwind");
  EXPECT_EQ(m.recent_swaps(1).by(), "tester@bench");
  EXPECT_EQ(m.recent_swaps(1).source(), "file mu012.textproto");
  EXPECT_EQ(m.recent_swaps(1).model_before(), "paper_downwind");
  EXPECT_EQ(m.recent_swaps(1).model_after(), "mu012");
  EXPECT_EQ(m.recent_swaps(0).after_state(), "final");         // replaced by the second swap
  EXPECT_EQ(m.recent_swaps(1).after_state(), "interrupted");   // in force at the kill
}

// The after-figures of a swap outlive a SIGKILL of the monitor that followed it: a swap, 300
// samples under the new model (health every 0.1 s), a pause past the second write of its
// figures (1 s after the first), SIGKILL, a new monitor on the same --state-dir: `status --json`
// shows the figures the killed monitor showed last, marked "interrupted", not "final".
TEST_F(LiveTest, AKilledMonitorsAfterSwapFiguresOutliveItMarkedInterrupted) {
  const std::vector<std::string> args = {"--health-period-s", "0.1", "--state-dir", new_state_dir()};
  live::MeasurementPublisher publisher(participant_.get(), "followed");
  std::unique_ptr<ChildProcess> first;
  ASSERT_NO_FATAL_FAILURE(start_monitor_and_swap(health_, publisher, args, "followed", first));
  publish_stream(publisher, paper_samples(), 300, 2000.0, 300);
  const v1::LiveStatus before = wait_for_status([](const v1::LiveStatus& s) {
    return s.monitors(0).recent_swaps_size() == 1 && s.monitors(0).recent_swaps(0).after_samples() == 300;
  });
  ASSERT_EQ(before.monitors_size(), 1);
  ASSERT_EQ(before.monitors(0).recent_swaps_size(), 1);
  const v1::SwapAuditRecord was = before.monitors(0).recent_swaps(0);
  ASSERT_EQ(was.after_samples(), 300u);
  EXPECT_EQ(was.after_state(), "following");
  EXPECT_GT(was.after_msy_rmse_nm(), 0.0);
  std::this_thread::sleep_for(2s);   // the write 1 s after the first has all 300 samples
  const std::string killed = before.monitors(0).monitor_id();
  first->signal(SIGKILL);
  ASSERT_EQ(first->wait_exit(10.0), 128 + SIGKILL);

  auto second = start_monitor(args);
  const v1::LiveStatus after = wait_for_status(
      [&](const v1::LiveStatus& s) { return s.monitors(0).monitor_id() != killed; });
  ASSERT_EQ(after.monitors_size(), 1);
  ASSERT_NE(after.monitors(0).monitor_id(), killed);
  ASSERT_EQ(after.monitors(0).recent_swaps_size(), 1);
  const v1::SwapAuditRecord& is = after.monitors(0).recent_swaps(0);
  EXPECT_EQ(is.model_after(), "paper_downwind");
  EXPECT_EQ(is.after_samples(), 300u);
  EXPECT_DOUBLE_EQ(is.after_msy_rmse_nm(), was.after_msy_rmse_nm());
  EXPECT_DOUBLE_EQ(is.after_msz_rmse_nm(), was.after_msz_rmse_nm());
  EXPECT_EQ(is.after_state(), "interrupted");
  const auto table = cli::testing::run_gearcoupling(on_test_domain({"status", "--discovery-s", "0.5"}));
  EXPECT_NE(table.out.find("(interrupted)"), std::string::npos) << table.out;   // the swaps' table says so too
  // A swap without an operator identity says so in words, as the dashboard does.
  EXPECT_NE(table.out.find("operator identity"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find(" none "), std::string::npos) << table.out;
}

// A damaged audit file (a line changed, a line of garbage, a last line torn by a kill) is
// reported in the log, line by line, and the monitor serves on with the records that are whole;
// the torn tail is cut off, so the next swap starts on its own line.
TEST_F(LiveTest, ADamagedAuditFileIsLoggedAndTheMonitorServesOnWithTheWholeRecords) {
  const std::string state_dir = new_state_dir();
  live::SwapEntry entry;
  entry.id = 0x1234;
  entry.test_cell = "damaged";
  entry.at = std::chrono::system_clock::now();
  entry.by = "alice@bench";
  entry.source = "file /etc/gearcoupling/models/dyno 1.textproto";
  entry.model_before = "paper";
  entry.model_after = "dyno1";
  const std::string whole = live::audit_line(live::swap_record_payload(entry));
  std::string changed = whole;
  changed[changed.find("alice")] = 'A';
  const std::string garbage = "hello, audit\n";
  const std::string torn = whole.substr(0, whole.size() / 2);
  cli::testing::write_file(state_dir + "/swap_audit.log", whole + changed + garbage + torn);

  std::string log;
  auto monitor = start_monitor({"--health-period-s", "0.1", "--state-dir", state_dir}, &log);
  live::MeasurementPublisher publisher(participant_.get(), "damaged");
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  publish_stream(publisher, paper_samples(), 300, 2000.0);
  const v1::LiveStatus status = wait_for_status(
      [](const v1::LiveStatus& s) { return s.test_cells_size() == 1 && s.test_cells(0).counts().taken() == 300; });
  ASSERT_EQ(status.monitors_size(), 1);
  ASSERT_EQ(status.monitors(0).recent_swaps_size(), 1);
  EXPECT_EQ(status.monitors(0).recent_swaps(0).by(), "alice@bench");
  EXPECT_EQ(status.monitors(0).recent_swaps(0).source(), entry.source);
  EXPECT_TRUE(monitor->running());
  const std::string logged = read_file(log);
  EXPECT_NE(logged.find("line 2 skipped: hash"), std::string::npos) << logged;
  EXPECT_NE(logged.find("line 3 skipped: version"), std::string::npos) << logged;
  EXPECT_NE(logged.find("line 4 is torn"), std::string::npos) << logged;
  EXPECT_EQ(read_file(state_dir + "/swap_audit.log"), whole + changed + garbage);
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
  auto no_state_dir = start_monitor({"--state-dir", cli::testing::temp_path("absent")}, &log);
  EXPECT_EQ(no_state_dir->wait_exit(20.0), 2);
  EXPECT_NE(read_file(log).find("--state-dir"), std::string::npos) << read_file(log);
}

}  // namespace
}  // namespace gc::test
