// Issue 23, finding 3: test-cell names are unbounded. 5,000 distinct names in one burst, as
// anyone allowed to publish on the live topics could send them, leave the monitor following
// and the dashboard showing at most --max-cells (64 by default), the rest refused and counted,
// /metrics under 1 MB, each process under +64 MB of resident memory and the dashboard idle
// with no browser. Real processes on the test's own loopback domain.
#include <chrono>
#include <functional>
#include <memory>
#include <regex>
#include <set>
#include <thread>

#include "live/health_wire.h"
#include "live/live_qos.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/random_id.h"
#include "protocol/topics.h"
#include "protocol/samples.h"
#include "tests/live/http_get.h"
#include "tests/live/live_fixture.h"
#include "tests/live/proc_status.h"
#include "tests/live/sample_stream.h"

namespace gc::test {
namespace {

using cli::testing::read_file;
using namespace std::chrono_literals;

constexpr int kBurstCells = 5000;
constexpr std::size_t kDefaultMaxCells = 64;
constexpr long kMostGrowthKb = 64 * 1024;
constexpr std::size_t kMostMetricsBytes = 1 << 20;

std::string burst_cell(int k) { return "burst-" + std::to_string(k); }

protocol::Entity make_writer(const protocol::Entity& publisher, const protocol::Entity& topic,
                             const protocol::Qos& qos) {
  return protocol::Entity(protocol::check_dds(
      dds_create_writer(publisher.get(), topic.get(), qos.get(), nullptr), "dds_create_writer"));
}

/// dds_write, again while a reliable reader makes it wait (its max blocking time is 1 s).
void write_reliably(dds_entity_t writer, const void* sample) {
  for (int attempt = 0; attempt < 30; ++attempt) {
    if (dds_write(writer, sample) != DDS_RETCODE_TIMEOUT) return;
  }
  FAIL() << "dds_write timed out 30 times";
}

/// The distinct test cells whose health a reader of the test's own has seen.
class HealthNames {
 public:
  explicit HealthNames(dds_entity_t participant)
      : subscriber_(live::make_live_subscriber(participant)),
        topic_(live::make_health_topic(participant)),
        reader_(protocol::check_dds(dds_create_reader(subscriber_.get(), topic_.get(),
                                                      live::health_reader_qos().get(), nullptr),
                                    "dds_create_reader(health)")) {}
  std::size_t count() {
    for (;;) {
      protocol::LoanedSamples<gearcoupling_CellHealth> samples(reader_.get());
      if (samples.size() == 0) return names_.size();
      for (std::size_t i = 0; i < samples.size(); ++i) {
        if (samples.info(i).valid_data) names_.insert(samples[i].test_cell);
      }
    }
  }

 private:
  protocol::Entity subscriber_, topic_, reader_;
  std::set<std::string> names_;
};

/// Occurrences of `needle` in `text`.
std::size_t occurrences(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

/// One writer of measurement batches for many test-cell names: each name one batch of 10
/// valid samples, as a DAQ's first millisecond at 10 kHz.
class MeasurementBurst {
 public:
  explicit MeasurementBurst(dds_entity_t participant)
      : publisher_(live::make_live_publisher(participant)),
        topic_(live::make_measurement_topic(participant)),
        writer_(make_writer(publisher_, topic_, live::measurement_writer_qos())),
        optionals_(10) {
    const std::vector<RecordedSample> samples = paper_samples();
    for (std::size_t k = 0; k < 10; ++k) wire_.push_back(live::to_wire(samples[k], k + 1, optionals_[k]));
  }
  dds_entity_t writer() const { return writer_.get(); }
  /// One batch for each of the names burst_cell(0 ... count - 1).
  void publish(int count) {
    for (int k = 0; k < count; ++k) {
      gearcoupling_MeasurementBatch batch{};
      const std::string name = burst_cell(k);
      std::copy_n(name.c_str(), name.size() + 1, batch.test_cell);
      batch.run_id = protocol::random_id();
      batch.samples._buffer = wire_.data();
      batch.samples._length = batch.samples._maximum = static_cast<std::uint32_t>(wire_.size());
      write_reliably(writer_.get(), &batch);
    }
  }

 private:
  protocol::Entity publisher_, topic_, writer_;
  std::vector<live::MeasurementOptionals> optionals_;
  std::vector<gearcoupling_Measurement> wire_;
};

/// Waits until the monitor's log names a refusal (at most 20 s), then 3 health periods.
void wait_for_health_after_burst(const std::string& log, bool refusal_expected) {
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  while (refusal_expected && read_file(log).find("refused") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(100ms);
  }
  std::this_thread::sleep_for(3s);
}

TEST(LiveBounds, FiveThousandCellNamesInABurstLeaveTheMonitorFollowingAtMostMaxCells) {
  std::string log;
  auto monitor = start_monitor({"--dispose-s", "60"}, &log);
  protocol::Entity participant = live::make_participant(test_domain());
  HealthNames health(participant.get());
  MeasurementBurst burst(participant.get());
  ASSERT_TRUE(live::wait_for_readers(burst.writer(), 1, 20s)) << "the monitor never matched";
  std::this_thread::sleep_for(1s);
  const long before_kb = resident_kb(monitor->pid());

  burst.publish(kBurstCells);
  wait_for_health_after_burst(log, true);
  EXPECT_EQ(health.count(), kDefaultMaxCells);
  const std::string text = read_file(log);
  EXPECT_NE(text.find("refused: 64 test cells are followed, the most --max-cells allows"),
            std::string::npos) << text;
  // The first refusal, then a summary at most once a second (issue 38's refusal log), not a line per
  // name: the burst and the wait after it last a few seconds.
  EXPECT_LE(occurrences(text, "refused"), 6u) << "logged once and summarised, not per name:\n" << text.substr(0, 4000);
  const long growth_kb = resident_kb(monitor->pid()) - before_kb;
  EXPECT_LT(growth_kb, kMostGrowthKb);
  std::printf("monitor: %ld kB resident before %d names, +%ld kB after\n", before_kb, kBurstCells,
              growth_kb);
}

TEST(LiveBounds, TheMonitorTakesAtMost100KilobytesPerFollowedCell) {
  constexpr int kCells = 1000;
  std::string log;
  auto monitor = start_monitor({"--dispose-s", "60", "--max-cells", std::to_string(kCells)}, &log);
  protocol::Entity participant = live::make_participant(test_domain());
  HealthNames health(participant.get());
  MeasurementBurst burst(participant.get());
  ASSERT_TRUE(live::wait_for_readers(burst.writer(), 1, 20s)) << "the monitor never matched";
  std::this_thread::sleep_for(1s);
  const long before_kb = resident_kb(monitor->pid());

  burst.publish(kCells);
  wait_for_health_after_burst(log, false);
  ASSERT_EQ(health.count(), static_cast<std::size_t>(kCells));
  // Everything a followed cell costs: its CellMonitor and Cyclone's instances (measurement
  // reader, residual and health writers).
  const double per_cell_kb = static_cast<double>(resident_kb(monitor->pid()) - before_kb) / kCells;
  EXPECT_LT(per_cell_kb, 100.0);
  std::printf("monitor: %.1f kB resident per followed test cell (%d cells)\n", per_cell_kb, kCells);
}

TEST(LiveBounds, ModelSwapsForThousandsOfUnseenCellsAreKeptForAtMostTwiceMaxCells) {
  constexpr int kSwaps = 2000;
  std::string log;
  auto monitor = start_monitor({}, &log);
  protocol::Entity participant = live::make_participant(test_domain());
  protocol::Entity publisher = live::make_live_publisher(participant.get());
  protocol::Entity topic = live::make_model_topic(participant.get());
  protocol::Entity writer = make_writer(publisher, topic, live::model_qos());
  ASSERT_TRUE(live::wait_for_readers(writer.get(), 1, 20s)) << "the monitor never matched";
  std::this_thread::sleep_for(1s);
  const long before_kb = resident_kb(monitor->pid());
  // Each swap a text of its own (a comment makes it differ), so each is parsed into a model.
  const std::string paper = read_file(GC_SOURCE_DIR "/data/models/paper.textproto");
  const auto swap = [&](const std::string& name, const std::string& text) {
    gearcoupling_ModelSwap sample{};
    std::copy_n(name.c_str(), name.size() + 1, sample.test_cell);
    sample.model_text = const_cast<char*>(text.c_str());
    write_reliably(writer.get(), &sample);
  };
  for (int k = 0; k < kSwaps; ++k) swap(burst_cell(k), paper + "\n# " + std::to_string(k) + "\n");
  // Last, from the same writer (so taken after all the others), a swap the monitor refuses with
  // a warning: once it is in the log, every swap before it has been taken.
  swap("burst-last", "not a model");
  const auto deadline = std::chrono::steady_clock::now() + 120s;
  while (read_file(log).find("test cell burst-last: model swap refused") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(200ms);
  }
  ASSERT_NE(read_file(log).find("test cell burst-last: model swap refused"), std::string::npos);
  const std::string text = read_file(log);
  EXPECT_EQ(occurrences(text, "dropped for one of"), 1u) << text.substr(0, 4000);
  const long growth_kb = resident_kb(monitor->pid()) - before_kb;
  EXPECT_LT(growth_kb, kMostGrowthKb);
  std::printf("monitor: %d model swaps for unseen cells: +%ld kB resident\n", kSwaps, growth_kb);
}

/// The dashboard's address from the first line it prints ("listening on http://ADDR:PORT/").
int dashboard_port(const std::string& stdout_path) {
  const std::regex listening("listening on http://[^:]+:([0-9]+)/");
  for (int k = 0; k < 200; ++k) {
    std::smatch match;
    const std::string text = read_file(stdout_path);
    if (std::regex_search(text, match, listening)) return std::stoi(match[1]);
    std::this_thread::sleep_for(50ms);
  }
  return -1;
}

/// The value of an unlabelled sample of /metrics, -1 when absent.
double metric(const std::string& metrics, const std::string& name) {
  const std::regex line("\n" + name + " ([0-9.e+]+)");
  std::smatch match;
  return std::regex_search(metrics, match, line) ? std::stod(match[1]) : -1.0;
}

/// The test cells /metrics labels.
std::set<std::string> cells_in(const std::string& metrics) {
  std::set<std::string> shown;
  const std::regex label("test_cell=\"([^\"]+)\"");
  for (std::sregex_iterator it(metrics.begin(), metrics.end(), label), end; it != end; ++it) {
    shown.insert((*it)[1]);
  }
  return shown;
}

/// gearcoupling-dashboard on the test's domain and a free port, with a health and a residual
/// writer of the test's own matched to it, as a monitor (or anyone allowed to publish) has.
class DashboardBounds : public ::testing::Test {
 protected:
  void start(std::vector<std::string> extra_args = {}) {
    std::vector<std::string> args = {GC_DASHBOARD_BINARY, "--domain", std::to_string(test_domain()),
                                     "--listen", "127.0.0.1:0"};
    args.insert(args.end(), extra_args.begin(), extra_args.end());
    dashboard_ = std::make_unique<ChildProcess>(args, out_, std::vector<std::pair<std::string, std::string>>{},
                                                std::string{}, true);
    port_ = dashboard_port(out_);
    ASSERT_GT(port_, 0) << read_file(out_);
    ASSERT_TRUE(live::wait_for_readers(health_.get(), 1, 20s)) << "the dashboard never matched";
    ASSERT_TRUE(live::wait_for_readers(residuals_.get(), 1, 20s));
    std::this_thread::sleep_for(1s);
  }
  /// Health and one residual batch for burst_cell(first ... first + count - 1); with `dispose`
  /// their health is disposed afterwards (the cells are gone).
  void publish(int first, int count, bool dispose = false) {
    live::HealthReport report;
    report.model.model_name = "paper";
    report.worst_region = "at high torque the model is 10 % low";
    gearcoupling_Residual residual{1, 0.0, 1e4, 2e4, 1.1e4, 2.1e4};
    for (int k = first; k < first + count; ++k) {
      const std::string name = burst_cell(k);
      live::write_health(health_.get(), name, monitor_id_, false, report);
      gearcoupling_ResidualBatch batch{};
      std::copy_n(name.c_str(), name.size() + 1, batch.test_cell);
      batch.run_id = 1;
      batch.model_name = const_cast<char*>("paper");
      batch.decimation = 1;
      batch.residuals._buffer = &residual;
      batch.residuals._length = batch.residuals._maximum = 1;
      write_reliably(residuals_.get(), &batch);
      if (dispose) live::dispose_health(health_.get(), name);
    }
  }
  /// /metrics, polled (at most 20 s) until `ready` holds for it.
  std::string metrics_when(const std::function<bool(const std::string&)>& ready) {
    std::string metrics;
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    do {
      std::this_thread::sleep_for(200ms);
      metrics = http_get(port_, "/metrics").body;
    } while (!ready(metrics) && std::chrono::steady_clock::now() < deadline);
    return metrics;
  }
  pid_t pid() const { return dashboard_->pid(); }

  std::string out_ = cli::testing::temp_path("dashboard_out");
  std::unique_ptr<ChildProcess> dashboard_;
  int port_ = -1;
  protocol::Entity participant_ = live::make_participant(test_domain());
  protocol::Entity health_topic_ = live::make_health_topic(participant_.get());
  protocol::Entity residual_topic_ = live::make_residual_topic(participant_.get());
  protocol::Entity publisher_ = live::make_live_publisher(participant_.get());
  protocol::Entity health_ = make_writer(publisher_, health_topic_, live::health_writer_qos());
  protocol::Entity residuals_ = make_writer(publisher_, residual_topic_, live::residual_qos());
  std::uint64_t monitor_id_ = protocol::random_id();
};

TEST_F(DashboardBounds, FiveThousandCellHealthsInABurstLeaveTheDashboardShowingAtMostMaxCells) {
  start();
  const long before_kb = resident_kb(pid());
  publish(0, kBurstCells);
  // Every health sample has arrived once the refusals count all names beyond the first 64.
  const double beyond = kBurstCells - static_cast<double>(kDefaultMaxCells);
  const std::string metrics = metrics_when([&](const std::string& m) {
    return metric(m, "gearcoupling_dashboard_cells_refused_total") >= beyond;
  });
  EXPECT_GE(metric(metrics, "gearcoupling_dashboard_cells_refused_total"), beyond);
  EXPECT_EQ(cells_in(metrics).size(), kDefaultMaxCells);
  EXPECT_LT(metrics.size(), kMostMetricsBytes);
  const std::size_t state_bytes = http_get(port_, "/api/state").body.size();
  EXPECT_LT(state_bytes, kMostMetricsBytes);
  const long growth_kb = resident_kb(pid()) - before_kb;
  EXPECT_LT(growth_kb, kMostGrowthKb);
  EXPECT_EQ(occurrences(read_file(out_), "ignored"), 1u) << "logged once:\n" << read_file(out_);

  // No browser: the dashboard does (almost) nothing. 5 % of a core over 5 s is 0.25 s.
  const double cpu_before = cpu_seconds(pid());
  std::this_thread::sleep_for(5s);
  const double idle_cpu = (cpu_seconds(pid()) - cpu_before) / 5.0;
  EXPECT_LT(idle_cpu, 0.05);
  std::printf("dashboard: %ld kB resident before %d names, +%ld kB after; /metrics %zu bytes, "
              "/api/state %zu bytes; %.1f %% of a core with no browser\n",
              before_kb, kBurstCells, growth_kb, metrics.size(), state_bytes, 100.0 * idle_cpu);
}

TEST_F(DashboardBounds, GoneCellsMakeRoomForNewOnesAtOnceNotAfterTenMinutes) {
  start();
  publish(0, kDefaultMaxCells, /*dispose=*/true);
  metrics_when([](const std::string& m) { return cells_in(m).size() == kDefaultMaxCells; });
  publish(1000, kDefaultMaxCells);  // 64 other names, alive: each takes a gone one's place
  const std::string metrics = metrics_when([](const std::string& m) {
    return cells_in(m).count(burst_cell(1000 + kDefaultMaxCells - 1)) > 0;
  });
  const std::set<std::string> shown = cells_in(metrics);
  EXPECT_EQ(shown.size(), kDefaultMaxCells);
  EXPECT_EQ(shown.count(burst_cell(0)), 0u);
  EXPECT_EQ(shown.count(burst_cell(1000)), 1u);
  EXPECT_EQ(metric(metrics, "gearcoupling_dashboard_cells_refused_total"), 0.0);
}

TEST_F(DashboardBounds, ACellTakesAtMost16KilobytesOfTheDashboard) {
  constexpr int kCells = 256;   // the most --max-cells allows
  start({"--max-cells", std::to_string(kCells)});
  const long before_kb = resident_kb(pid());
  publish(0, kCells);
  const std::string metrics = metrics_when([&](const std::string& m) {
    return cells_in(m).size() == static_cast<std::size_t>(kCells);
  });
  ASSERT_EQ(cells_in(metrics).size(), static_cast<std::size_t>(kCells));
  const double per_cell_kb = static_cast<double>(resident_kb(pid()) - before_kb) / kCells;
  EXPECT_LT(per_cell_kb, 16.0);
  EXPECT_LT(metrics.size(), kMostMetricsBytes);
  std::printf("dashboard: %.1f kB resident per test cell, /metrics %zu bytes (%d cells)\n",
              per_cell_kb, metrics.size(), kCells);
}

TEST_F(DashboardBounds, FiveThousandServiceStatusesLeaveTheDashboardShowingAtMost64Instances) {
  start();
  protocol::Entity topic = protocol::make_status_topic(participant_.get());
  const protocol::Qos partition = protocol::partition_qos(protocol::kStatusPartition);
  protocol::Entity publisher(protocol::check_dds(
      dds_create_publisher(participant_.get(), partition.get(), nullptr), "dds_create_publisher"));
  protocol::Entity writer = make_writer(publisher, topic, protocol::status_qos(2.0));
  ASSERT_TRUE(live::wait_for_readers(writer.get(), 1, 20s));
  const long before_kb = resident_kb(pid());
  // Each status lists 6 calculations, as a service's does.
  std::vector<gearcoupling_CalculationStats> calculations(6);
  for (auto& c : calculations) c.calculation = const_cast<char*>("jam_angle");
  for (int k = 0; k < kBurstCells; ++k) {
    gearcoupling_ServiceStatus status{};
    status.instance_id = 1000 + k;
    status.request_partition = const_cast<char*>("gearcoupling.request.x");
    status.host = const_cast<char*>("attacker");
    status.accepting = true;
    status.calculations._buffer = calculations.data();
    status.calculations._length = status.calculations._maximum = 6;
    write_reliably(writer.get(), &status);
  }
  const double beyond = kBurstCells - 64.0;
  const std::string metrics = metrics_when([&](const std::string& m) {
    return metric(m, "gearcoupling_dashboard_instances_refused_total") >= beyond;
  });
  EXPECT_GE(metric(metrics, "gearcoupling_dashboard_instances_refused_total"), beyond);
  EXPECT_EQ(occurrences(metrics, "gearcoupling_instance_up{"), 64u);
  EXPECT_LT(metrics.size(), kMostMetricsBytes);
  EXPECT_LT(resident_kb(pid()) - before_kb, kMostGrowthKb);
  std::printf("dashboard: %d service statuses: /metrics %zu bytes, +%ld kB resident\n", kBurstCells,
              metrics.size(), resident_kb(pid()) - before_kb);
}

/// A connection asking for /events that never reads, with a small receive buffer: the server's
/// writes to it block once the socket buffers are full.
int stalled_stream(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  const int small = 4096;
  setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) return -1;
  const std::string request = "GET /events HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
  send(fd, request.data(), request.size(), 0);
  return fd;
}

TEST_F(DashboardBounds, BrowsersThatDoNotReadHoldBoundedMemoryAndTheRestAnswers) {
  constexpr int kStreams = 32;   // the default --max-streams
  start();
  publish(0, kDefaultMaxCells);
  metrics_when([](const std::string& m) { return cells_in(m).size() == kDefaultMaxCells; });
  const long before_kb = resident_kb(pid());
  const double cpu_before = cpu_seconds(pid());
  std::vector<int> streams;
  for (int k = 0; k < kStreams; ++k) streams.push_back(stalled_stream(port_));
  std::this_thread::sleep_for(10s);
  const double cpu = (cpu_seconds(pid()) - cpu_before) / 10.0;
  const long growth_kb = resident_kb(pid()) - before_kb;
  const auto asked = std::chrono::steady_clock::now();
  const HttpAnswer metrics = http_get(port_, "/metrics", 1.0);
  const double took_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
  for (int fd : streams) close(fd);
  EXPECT_EQ(metrics.status, 200);
  EXPECT_LT(took_s, 1.0);
  EXPECT_LT(growth_kb, kMostGrowthKb);
  std::printf("dashboard: %d browsers that do not read, %d cells: +%ld kB resident (%.0f kB a "
              "browser), %.1f %% of a core; /metrics in %.3f s; %s updates dropped\n",
              kStreams, static_cast<int>(kDefaultMaxCells), growth_kb,
              static_cast<double>(growth_kb) / kStreams, 100.0 * cpu, took_s,
              std::to_string(metric(metrics.body, "gearcoupling_dashboard_updates_dropped_total")).c_str());
}

}  // namespace
}  // namespace gc::test
