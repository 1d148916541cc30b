// The live test cell under DDS Security (docs/security.md, "Live roles"): the real
// gearcoupling-monitor with a monitor identity, a cell identity replaying measurements, an
// operator identity swapping the model, a dashboard identity reading the health, and each
// role refused what it does not need. Certificates made at test time by make-security.sh.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clients/status/cell_board.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "live/model_swap_publisher.h"
#include "live/replay.h"
#include "tests/cli/run_process.h"
#include "tests/service/secure_cell.h"
#include "tests/service/secure_cell_test.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using namespace std::chrono_literals;
using protocol::Entity;

// Local ids of the in-process identities' domains (all on test_domain() on the wire).
constexpr int kCellDomain = 223;
constexpr int kDashboardDomain = 224;
constexpr int kOperatorDomain = 225;
constexpr int kMonitorDomain = 226;

constexpr const char* kRecording = GC_SOURCE_DIR "/data/recordings/hidden_eccentricity_torque_ramp.csv";
constexpr std::uint64_t kRecordingSamples = 1000;  // rows of that recording

using TopicMaker = Entity (*)(dds_entity_t);

/// A board of the health topic alone: what an operator identity may read.
status::CellBoardOptions health_only() {
  status::CellBoardOptions options;
  options.read_residuals = false;
  return options;
}

/// What creating a writer (or reader) of a live topic on `participant` gives: a positive handle
/// when its permissions allow it, else Cyclone's refusal (DDS_RETCODE_NOT_ALLOWED_BY_SECURITY,
/// from the topic already when the grant names it for neither direction).
dds_return_t try_live_endpoint(dds_entity_t participant, TopicMaker make_topic, bool writer) {
  try {
    const Entity topic = make_topic(participant);
    const Entity group = writer ? live::make_live_publisher(participant)
                                : live::make_live_subscriber(participant);
    const dds_entity_t endpoint = writer ? dds_create_writer(group.get(), topic.get(), nullptr, nullptr)
                                         : dds_create_reader(group.get(), topic.get(), nullptr, nullptr);
    return endpoint > 0 ? 1 : endpoint;  // the entities go with this scope
  } catch (const protocol::DdsError& e) {
    return e.code();
  }
}

class LiveRoles : public test::SecureCellTest {
 protected:
  void SetUp() override {
    make_cell("--monitor m --cell c --operator o");
  }
  std::unique_ptr<test::ChildProcess> start_monitor() const {
    return std::make_unique<test::ChildProcess>(
        std::vector<std::string>{GC_MONITOR_BINARY, "--domain", std::to_string(test::test_domain()),
                                 "--health-period-s", "0.2", "--log-level", "warn"},
        cell_->dir() + "/monitor.log",
        std::vector<std::pair<std::string, std::string>>{{"CYCLONEDDS_URI", cell_->uri("monitor-m")}});
  }
};

TEST_F(LiveRoles, TheMonitorsHealthOfAReplayedCellReachesTheDashboardAndTheOperatorSwapsTheModel) {
  const auto monitor = start_monitor();
  const test::LocalDomain dashboard_domain(kDashboardDomain, cell_->uri("dashboard-main"));
  const Entity dashboard = dashboard_domain.participant();
  status::CellBoard health(dashboard.get(), health_only());

  const test::LocalDomain cell_domain(kCellDomain, cell_->uri("cell-c"));
  const Entity cell = cell_domain.participant();
  live::ReplayOptions replay;
  replay.test_cell = "secure-cell";
  replay.speed = 50.0;
  replay.wait_s = 30.0;
  const live::ReplayResult replayed = live::replay_recording(cell.get(), kRecording, replay);
  EXPECT_EQ(replayed.published, kRecordingSamples);

  const auto seen = health.wait_for(
      "secure-cell", [](const status::HealthView& h) { return h.taken >= kRecordingSamples; }, 30s);
  ASSERT_TRUE(seen.has_value()) << cli::testing::read_file(cell_->dir() + "/monitor.log");
  EXPECT_EQ(seen->taken, kRecordingSamples);
  EXPECT_EQ(seen->model_name, "paper");

  // The operator swaps the model in and sees the monitor take it (its health names it).
  const test::LocalDomain operator_domain(kOperatorDomain, cell_->uri("operator-o"));
  const Entity op = operator_domain.participant();
  live::ModelSwapPublisher swaps(op.get());
  status::CellBoard operator_view(op.get(), health_only());
  ASSERT_TRUE(swaps.wait_for_readers(1, 30s));
  swaps.publish("secure-cell", cli::testing::read_file(GC_SOURCE_DIR "/data/models/paper.textproto"));
  EXPECT_TRUE(operator_view
                  .wait_for("secure-cell",
                            [](const status::HealthView& h) { return h.previous_model_name.has_value(); },
                            30s)
                  .has_value());
}

struct Permission {
  const char* identity;
  int local_domain;
  const char* topic_name;
  TopicMaker topic;
  bool writer;
  bool allowed;
};

TEST_F(LiveRoles, EachRoleMayPublishAndReadOnlyWhatItNeeds) {
  const Permission table[] = {
      // A dashboard reads the health and residuals and publishes nothing.
      {"dashboard-main", kDashboardDomain, "health", live::make_health_topic, false, true},
      {"dashboard-main", kDashboardDomain, "residual", live::make_residual_topic, false, true},
      {"dashboard-main", kDashboardDomain, "measurement", live::make_measurement_topic, true, false},
      {"dashboard-main", kDashboardDomain, "health", live::make_health_topic, true, false},
      {"dashboard-main", kDashboardDomain, "residual", live::make_residual_topic, true, false},
      {"dashboard-main", kDashboardDomain, "model", live::make_model_topic, true, false},
      // The monitor publishes health and residuals, reads measurements and models.
      {"monitor-m", kMonitorDomain, "health", live::make_health_topic, true, true},
      {"monitor-m", kMonitorDomain, "residual", live::make_residual_topic, true, true},
      {"monitor-m", kMonitorDomain, "measurement", live::make_measurement_topic, false, true},
      {"monitor-m", kMonitorDomain, "model", live::make_model_topic, false, true},
      {"monitor-m", kMonitorDomain, "measurement", live::make_measurement_topic, true, false},
      {"monitor-m", kMonitorDomain, "model", live::make_model_topic, true, false},
      // The cell publishes and records measurements, nothing else.
      {"cell-c", kCellDomain, "measurement", live::make_measurement_topic, true, true},
      {"cell-c", kCellDomain, "measurement", live::make_measurement_topic, false, true},
      {"cell-c", kCellDomain, "health", live::make_health_topic, true, false},
      {"cell-c", kCellDomain, "model", live::make_model_topic, true, false},
      // The operator publishes models and reads the health.
      {"operator-o", kOperatorDomain, "model", live::make_model_topic, true, true},
      {"operator-o", kOperatorDomain, "health", live::make_health_topic, false, true},
      {"operator-o", kOperatorDomain, "health", live::make_health_topic, true, false},
      {"operator-o", kOperatorDomain, "measurement", live::make_measurement_topic, true, false},
      // A client of the service has no live rights.
      {"client-a", 227, "measurement", live::make_measurement_topic, true, false},
      {"client-a", 227, "health", live::make_health_topic, false, false},
  };
  for (const Permission& p : table) {
    const test::LocalDomain domain(p.local_domain, cell_->uri(p.identity));
    const Entity participant = domain.participant();
    const dds_return_t got = try_live_endpoint(participant.get(), p.topic, p.writer);
    EXPECT_EQ(got, p.allowed ? 1 : DDS_RETCODE_NOT_ALLOWED_BY_SECURITY)
        << p.identity << (p.writer ? " writing " : " reading ") << p.topic_name;
  }
}

}  // namespace
}  // namespace gc
