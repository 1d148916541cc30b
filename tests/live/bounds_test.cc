// Issue 23, finding 3: test-cell names are unbounded. 5,000 distinct names in one burst, as
// anyone allowed to publish on the live topics could send them, leave the monitor following
// and the dashboard showing at most --max-cells (64 by default), the rest refused and counted,
// /metrics under 1 MB, each process under +64 MB of resident memory and the dashboard idle
// with no browser. Real processes on the test's own loopback domain.
#include <chrono>
#include <regex>
#include <set>
#include <thread>

#include "live/health_wire.h"
#include "live/live_qos.h"
#include "protocol/random_id.h"
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

TEST(LiveBounds, FiveThousandCellNamesInABurstLeaveTheMonitorFollowingAtMostMaxCells) {
  std::string log;
  auto monitor = start_monitor({"--dispose-s", "60"}, &log);
  protocol::Entity participant = live::make_participant(test_domain());
  HealthNames health(participant.get());
  protocol::Entity publisher = live::make_live_publisher(participant.get());
  protocol::Entity topic = live::make_measurement_topic(participant.get());
  protocol::Entity writer = make_writer(publisher, topic, live::measurement_writer_qos());
  ASSERT_TRUE(live::wait_for_readers(writer.get(), 1, 20s)) << "the monitor never matched";
  std::this_thread::sleep_for(1s);
  const long before_kb = resident_kb(monitor->pid());

  // Each name one batch of 10 valid samples, as a DAQ's first millisecond at 10 kHz.
  const std::vector<RecordedSample> samples = paper_samples();
  std::vector<live::MeasurementOptionals> optionals(10);
  std::vector<gearcoupling_Measurement> wire;
  for (std::size_t k = 0; k < 10; ++k) wire.push_back(live::to_wire(samples[k], k + 1, optionals[k]));
  for (int k = 0; k < kBurstCells; ++k) {
    gearcoupling_MeasurementBatch batch{};
    const std::string name = burst_cell(k);
    std::copy_n(name.c_str(), name.size() + 1, batch.test_cell);
    batch.run_id = protocol::random_id();
    batch.samples._buffer = wire.data();
    batch.samples._length = batch.samples._maximum = static_cast<std::uint32_t>(wire.size());
    write_reliably(writer.get(), &batch);
  }

  // Health comes once a second per followed cell; 3 periods after the burst all are in.
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  while (read_file(log).find("refused") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(100ms);
  }
  std::this_thread::sleep_for(3s);
  EXPECT_EQ(health.count(), kDefaultMaxCells);
  const std::string text = read_file(log);
  EXPECT_NE(text.find("refused: 64 test cells are followed, the most --max-cells allows"),
            std::string::npos) << text;
  EXPECT_EQ(occurrences(text, "refused"), 1u) << "logged once, not per name:\n" << text.substr(0, 4000);
  const long growth_kb = resident_kb(monitor->pid()) - before_kb;
  EXPECT_LT(growth_kb, kMostGrowthKb);
  std::printf("monitor: %ld kB resident before the burst, +%ld kB after\n", before_kb, growth_kb);
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

TEST(LiveBounds, FiveThousandCellHealthsInABurstLeaveTheDashboardShowingAtMostMaxCells) {
  const std::string out = cli::testing::temp_path("dashboard_out");
  ChildProcess dashboard({GC_DASHBOARD_BINARY, "--domain", std::to_string(test_domain()),
                          "--listen", "127.0.0.1:0"},
                         out, {}, {}, true);
  const int port = dashboard_port(out);
  ASSERT_GT(port, 0) << read_file(out);
  protocol::Entity participant = live::make_participant(test_domain());
  protocol::Entity health_topic = live::make_health_topic(participant.get());
  protocol::Entity residual_topic = live::make_residual_topic(participant.get());
  protocol::Entity publisher = live::make_live_publisher(participant.get());
  protocol::Entity health = make_writer(publisher, health_topic, live::health_writer_qos());
  protocol::Entity residuals = make_writer(publisher, residual_topic, live::residual_qos());
  ASSERT_TRUE(live::wait_for_readers(health.get(), 1, 20s)) << "the dashboard never matched";
  ASSERT_TRUE(live::wait_for_readers(residuals.get(), 1, 20s));
  std::this_thread::sleep_for(1s);
  const long before_kb = resident_kb(dashboard.pid());

  live::HealthReport report;
  report.model.model_name = "paper";
  report.worst_region = "at high torque the model is 10 % low";
  gearcoupling_Residual residual{1, 0.0, 1e4, 2e4, 1.1e4, 2.1e4};
  const std::uint64_t monitor_id = protocol::random_id();
  for (int k = 0; k < kBurstCells; ++k) {
    const std::string name = burst_cell(k);
    live::write_health(health.get(), name, monitor_id, false, report);
    gearcoupling_ResidualBatch batch{};
    std::copy_n(name.c_str(), name.size() + 1, batch.test_cell);
    batch.run_id = 1;
    batch.model_name = const_cast<char*>("paper");
    batch.decimation = 1;
    batch.residuals._buffer = &residual;
    batch.residuals._length = batch.residuals._maximum = 1;
    write_reliably(residuals.get(), &batch);
  }

  // Every health sample has arrived once the refusals count all names beyond the first 64.
  std::string metrics;
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  do {
    std::this_thread::sleep_for(200ms);
    metrics = http_get(port, "/metrics").body;
  } while (metric(metrics, "gearcoupling_dashboard_cells_refused_total") <
               kBurstCells - static_cast<double>(kDefaultMaxCells) &&
           std::chrono::steady_clock::now() < deadline);
  EXPECT_GE(metric(metrics, "gearcoupling_dashboard_cells_refused_total"),
            kBurstCells - static_cast<double>(kDefaultMaxCells));
  std::set<std::string> shown;
  const std::regex label("test_cell=\"([^\"]+)\"");
  for (std::sregex_iterator it(metrics.begin(), metrics.end(), label), end; it != end; ++it) {
    shown.insert((*it)[1]);
  }
  EXPECT_EQ(shown.size(), kDefaultMaxCells);
  EXPECT_LT(metrics.size(), kMostMetricsBytes);
  EXPECT_LT(http_get(port, "/api/state").body.size(), kMostMetricsBytes);
  const long growth_kb = resident_kb(dashboard.pid()) - before_kb;
  EXPECT_LT(growth_kb, kMostGrowthKb);

  // No browser: the dashboard does (almost) nothing. 5 % of a core over 5 s is 0.25 s.
  const double cpu_before = cpu_seconds(dashboard.pid());
  std::this_thread::sleep_for(5s);
  const double idle_cpu = (cpu_seconds(dashboard.pid()) - cpu_before) / 5.0;
  EXPECT_LT(idle_cpu, 0.05);
  std::printf("dashboard: %ld kB resident before the burst, +%ld kB after; /metrics %zu bytes; "
              "%.1f %% of a core with no browser\n",
              before_kb, growth_kb, metrics.size(), 100.0 * idle_cpu);
}

}  // namespace
}  // namespace gc::test
