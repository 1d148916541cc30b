// Issue 38: what a model swap or a measurement batch from anyone allowed to publish may do to the
// monitor (plain mode here; tests/service/live_security_test.cc under DDS Security). A swap names
// no file of the monitor's host, kills no monitor, also not one restarted into it; 100 hostile
// swaps leave the monitor within its ceiling; a flood of bad batches is counted by kind and
// logged at most once a second; an oversized batch is refused by name.
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "gearcoupling.h"
#include "live/live_names.h"
#include "live/live_qos.h"
#include "live/model_swap_publisher.h"
#include "tests/live/live_fixture.h"
#include "tests/live/live_status.h"
#include "tests/live/proc_status.h"
#include "tests/live/sample_stream.h"

namespace gc::test {
namespace {

using namespace std::chrono_literals;
using cli::testing::read_file;
using status::HealthView;

std::uint64_t refusals_of(const v1::LiveStatus& status, const std::string& kind) {
  if (status.monitors_size() != 1) return 0;
  const auto& refusals = status.monitors(0).refusals();
  const auto found = refusals.find(kind);
  return found == refusals.end() ? 0 : found->second;
}

bool taken(const std::optional<HealthView>& health, std::uint64_t count) {
  return health.has_value() && health->taken == count;
}

// Finding 1: `coupling_file` of a swap was opened on the monitor's host: an absolute path was
// read, the refusal quoted the file and told whether it existed, and /dev/zero killed the
// monitor (std::bad_alloc), again at each restart while the swap's writer lived.
TEST_F(LiveTest, ASwapNamingAFileIsRefusedUnreadAndTheMonitorServesOnAlsoWhenRestartedIntoIt) {
  std::string log;
  auto monitor = start_monitor({"--health-period-s", "0.1"}, &log);
  live::MeasurementPublisher attacked(participant_.get(), "attacked");
  live::MeasurementPublisher other(participant_.get(), "other");
  live::ModelSwapPublisher swaps(participant_.get(), {"attacked"});
  ASSERT_TRUE(attacked.wait_for_readers(1, 10s));
  ASSERT_TRUE(other.wait_for_readers(1, 10s));
  ASSERT_TRUE(swaps.wait_for_readers(1, 10s));
  const auto samples = paper_samples();
  publish_stream(attacked, samples, 100, 5000.0);
  publish_stream(other, samples, 100, 5000.0);
  ASSERT_TRUE(taken(health_.wait_for("attacked", [](const HealthView& h) { return h.taken == 100; }, 10s), 100));
  ASSERT_TRUE(taken(health_.wait_for("other", [](const HealthView& h) { return h.taken == 100; }, 10s), 100));

  std::vector<std::string> refusals;
  const std::vector<std::string> paths = {"/etc/passwd", "/nonexistent/coupling.textproto", "/dev/zero"};
  for (std::size_t i = 0; i < paths.size(); ++i) {
    swaps.publish("attacked", "name: \"stolen\"\ncoupling_file: \"" + paths[i] + "\"\n");
    const v1::LiveStatus status = wait_for_status(
        [&](const v1::LiveStatus& s) { return refusals_of(s, "swap_bad_model") == i + 1; });
    ASSERT_EQ(refusals_of(status, "swap_bad_model"), i + 1) << paths[i] << "\n" << read_file(log);
    const auto health = health_.wait_for(
        "attacked", [](const HealthView& h) { return !h.last_model_refusal.empty(); }, 10s);
    ASSERT_TRUE(health.has_value());
    EXPECT_EQ(health->model_name, "paper");
    refusals.push_back(health->last_model_refusal);
  }
  EXPECT_TRUE(monitor->running());
  for (const std::string& refusal : refusals) {
    // The same words whatever the path: no file's content, nor whether it exists.
    EXPECT_EQ(refusal, refusals.front());
    EXPECT_NE(refusal.find("model.coupling_file"), std::string::npos) << refusal;
    EXPECT_EQ(refusal.find("root"), std::string::npos) << refusal;
    EXPECT_EQ(refusal.find("passwd"), std::string::npos) << refusal;
  }
  // Every other cell is still monitored.
  publish_stream(other, samples, 100, 5000.0, 100);
  EXPECT_TRUE(taken(health_.wait_for("other", [](const HealthView& h) { return h.taken == 200; }, 10s), 200));

  // Restarted while the swap's writer still offers /dev/zero (TRANSIENT_LOCAL): it stays up and
  // says why, three times.
  for (int restart = 0; restart < 3; ++restart) {
    monitor->signal(SIGKILL);
    monitor = start_monitor({"--health-period-s", "0.1"}, &log);
    const v1::LiveStatus status =
        wait_for_status([](const v1::LiveStatus& s) { return refusals_of(s, "swap_bad_model") == 1; });
    EXPECT_EQ(refusals_of(status, "swap_bad_model"), 1u) << read_file(log);
    ASSERT_TRUE(attacked.wait_for_readers(1, 10s));
    publish_stream(attacked, samples, 50, 5000.0, 100 + 50 * restart);
    const auto health = health_.wait_for(
        "attacked", [](const HealthView& h) { return h.taken == 50 && !h.last_model_refusal.empty(); }, 10s);
    ASSERT_TRUE(health && health->taken == 50) << read_file(log);
    EXPECT_EQ(health->last_model_refusal, refusals.front());
    EXPECT_TRUE(monitor->running()) << read_file(log);
  }
}

std::string expression_model(const std::string& name, int first_period_s, int terms) {
  std::string text = "name: \"" + name + "\"\ncoupling: \"nrel_upwind\"\neffects { name: \"expression\"\n";
  for (int k = 0; k < terms; ++k) {
    text += "  parameters { name: \"time_cycle_" + std::to_string(first_period_s + k) +
            "s_sin_on_y\" value: 1 }\n";
  }
  return text + "}\n";
}

// Finding 2: expression terms were interned for the life of the process (+14.5 MB for each 1 MB
// expression swap) and a 10 MB description was accepted. 100 hostile swaps of one cell, a
// quarter each: 1 MB texts, over-long names, the largest accepted expression (64 terms) with
// terms no swap used before, and swaps back to the paper model. Each is waited for in the
// cell's health (the swap topic keeps the latest per cell). The monitor stays within 16 MB of
// where it started (docs/architecture.md, "What one test cell may cost").
TEST_F(LiveTest, AHundredHostileSwapsLeaveTheMonitorWithinItsCeiling) {
  std::string log;
  auto monitor = start_monitor({"--health-period-s", "0.05", "--no-diagnosis"}, &log);
  live::MeasurementPublisher publisher(participant_.get(), "hostile");
  live::ModelSwapPublisher swaps(participant_.get(), {"hostile"});
  ASSERT_TRUE(publisher.wait_for_readers(1, 10s));
  ASSERT_TRUE(swaps.wait_for_readers(1, 10s));
  const auto samples = paper_samples();
  publish_stream(publisher, samples, 50, 5000.0);
  ASSERT_TRUE(taken(health_.wait_for("hostile", [](const HealthView& h) { return h.taken == 50; }, 10s), 50));
  const std::string paper = read_file(GC_SOURCE_DIR "/data/models/paper.textproto");
  // Warm: one of each kind before the first figure.
  swaps.publish("hostile", expression_model("warm", 100000, 64));
  const auto warm = health_.wait_for("hostile", [](const HealthView& h) { return h.model_name == "warm"; }, 10s);
  ASSERT_TRUE(warm && warm->model_name == "warm") << read_file(log);
  const long before_kb = resident_kb(monitor->pid());

  for (int i = 0; i < 100; ++i) {
    std::function<bool(const HealthView&)> taken_swap;
    const std::string marker = std::to_string(1'000'000 + i);
    switch (i % 4) {
      case 0: {   // 1 MB of expression text: refused by its size before it is parsed
        std::string text = expression_model("big" + marker, 2, 1);
        text += "# " + std::string(1'000'000 + static_cast<std::size_t>(i), 'x') + "\n";
        swaps.publish("hostile", text);
        const std::string size = std::to_string(text.size()) + " bytes";
        taken_swap = [size](const HealthView& h) { return h.last_model_refusal.find(size) != std::string::npos; };
        break;
      }
      case 1: {   // a name of 200 + i bytes
        const std::string name(200 + static_cast<std::size_t>(i), 'n');
        swaps.publish("hostile", "name: \"" + name + "\" coupling: \"nrel_upwind\"");
        const std::string size = std::to_string(name.size()) + " bytes";
        taken_swap = [size](const HealthView& h) { return h.last_model_refusal.find(size) != std::string::npos; };
        break;
      }
      case 2: {   // accepted: 64 terms no swap used before
        const std::string name = "expr" + marker;
        swaps.publish("hostile", expression_model(name, 2 + 64 * i, 64));
        taken_swap = [name](const HealthView& h) { return h.model_name == name; };
        break;
      }
      default: {
        const std::string name = "paper" + marker;
        swaps.publish("hostile", "name: \"" + name + "\"\n" + paper.substr(paper.find("\ncoupling:") + 1));
        taken_swap = [name](const HealthView& h) { return h.model_name == name; };
      }
    }
    const auto health = health_.wait_for("hostile", taken_swap, 10s);
    ASSERT_TRUE(health && taken_swap(*health)) << "swap " << i << "\n" << read_file(log);
  }
  ASSERT_TRUE(monitor->running());
  const long after_kb = resident_kb(monitor->pid());
  std::printf("monitor: %ld kB resident before 100 hostile swaps, %ld kB after (%+ld kB)\n", before_kb,
              after_kb, after_kb - before_kb);
  EXPECT_LT(after_kb - before_kb, 16 * 1024);
}

/// A raw measurement writer in the shared partition: it may put anything in test_cell.
class RawBatches {
 public:
  explicit RawBatches(dds_entity_t participant)
      : publisher_(live::make_live_publisher(participant)),
        topic_(live::make_measurement_topic(participant)),
        writer_(dds_create_writer(publisher_.get(), topic_.get(), live::measurement_writer_qos().get(), nullptr)) {}
  dds_entity_t writer() const { return writer_.get(); }
  void write(const char* test_cell, std::vector<gearcoupling_Measurement>& samples) {
    gearcoupling_MeasurementBatch batch{};
    std::snprintf(batch.test_cell, sizeof batch.test_cell, "%s", test_cell);
    batch.run_id = 7;
    batch.samples._buffer = samples.data();
    batch.samples._length = batch.samples._maximum = static_cast<std::uint32_t>(samples.size());
    batch.samples._release = false;
    ASSERT_EQ(dds_write(writer_.get(), &batch), DDS_RETCODE_OK);
  }

 private:
  protocol::Entity publisher_, topic_, writer_;
};

std::size_t lines_with(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
  return count;
}

// Finding 7: a batch whose test-cell name had odd bytes wrote one warning line per batch (4.5 MB
// of log in 0.4 s) and no counter counted it; an oversized batch vanished without a word.
// 3,000 such batches and one of 5,000 samples: every one counted in MonitorStatus by kind, the
// log holds the first of each kind and at most a summary a second.
TEST_F(LiveTest, AFloodOfBadBatchesIsCountedByKindAndLoggedAtMostOnceASecond) {
  std::string log;
  auto monitor = start_monitor({"--health-period-s", "0.1"}, &log);
  RawBatches raw(participant_.get());
  ASSERT_TRUE(live::wait_for_readers(raw.writer(), 1, 10s));
  std::vector<gearcoupling_Measurement> one(1);
  one[0].sequence_number = 1;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 3000; ++i) raw.write("\x01\x7f garbage\xff", one);
  std::vector<gearcoupling_Measurement> many(live::kMaxBatchSamples + 904);
  for (std::size_t k = 0; k < many.size(); ++k) many[k].sequence_number = k + 1;
  raw.write("oversized", many);
  const v1::LiveStatus status = wait_for_status([](const v1::LiveStatus& s) {
    return refusals_of(s, "batch_bad_name") == 3000 && refusals_of(s, "batch_oversized") == 1;
  });
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(refusals_of(status, "batch_bad_name"), 3000u);
  EXPECT_EQ(refusals_of(status, "batch_oversized"), 1u);
  EXPECT_TRUE(monitor->running());
  const std::string text = read_file(log);
  EXPECT_GE(lines_with(text, "refusal batch_bad_name"), 1u) << text.substr(0, 2000);
  EXPECT_LE(lines_with(text, "batch_bad_name"), 2u + static_cast<std::size_t>(elapsed_s)) << text.substr(0, 2000);
  EXPECT_NE(text.find("measurement batch for test cell oversized refused: 5000 samples, allowed 0 to 4096"),
            std::string::npos) << text.substr(0, 2000);
  EXPECT_LT(text.size(), 64u * 1024u);
  // No cell was made of either.
  EXPECT_FALSE(health_.wait_for("oversized", [](const HealthView&) { return true; }, 1s).has_value());
}

}  // namespace
}  // namespace gc::test
