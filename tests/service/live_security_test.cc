// The live test cell under DDS Security (docs/security.md, "Live roles"): the real
// gearcoupling-monitor with a monitor identity, a cell identity replaying measurements, an
// operator identity swapping the model, a dashboard identity reading the health, and each
// role refused what it does not need. Certificates made at test time by make-security.sh.
#include <signal.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <thread>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clients/status/cell_board.h"
#include "clients/status/monitor_board.h"
#include "live/live_names.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "live/measurement_publisher.h"
#include "live/model_swap_publisher.h"
#include "live/replay.h"
#include "protocol/matching.h"
#include "protocol/qos.h"
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
constexpr int kCellDDomain = 222;

constexpr const char* kRecording = GC_SOURCE_DIR "/data/recordings/hidden_eccentricity_torque_ramp.csv";
constexpr std::uint64_t kRecordingSamples = 1000;  // rows of that recording

using TopicMaker = Entity (*)(dds_entity_t);

/// A board of the health topic alone: what an operator identity may read.
status::CellBoardOptions health_only() {
  status::CellBoardOptions options;
  options.read_residuals = false;
  return options;
}

/// What creating a writer (or reader) of a live topic on `participant` in `partition` gives: a
/// positive handle when its permissions allow it, else Cyclone's refusal
/// (DDS_RETCODE_NOT_ALLOWED_BY_SECURITY, from the topic already when the grant names it for
/// neither direction).
dds_return_t try_live_endpoint(dds_entity_t participant, TopicMaker make_topic, bool writer,
                               const std::string& partition) {
  try {
    const Entity topic = make_topic(participant);
    const protocol::Qos in = protocol::partition_qos(partition);
    const Entity group(writer ? dds_create_publisher(participant, in.get(), nullptr)
                              : dds_create_subscriber(participant, in.get(), nullptr));
    if (group.get() < 0) return group.get();
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
    make_cell("--monitor m --cell c --cell d --operator o --cells c");
  }
  std::unique_ptr<test::ChildProcess> start_monitor(std::vector<std::string> extra = {}) const {
    std::vector<std::string> args{GC_MONITOR_BINARY, "--domain", std::to_string(test::test_domain()),
                                  "--health-period-s", "0.2", "--log-level", "warn"};
    args.insert(args.end(), extra.begin(), extra.end());
    return std::make_unique<test::ChildProcess>(
        args,
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
  replay.test_cell = "c";
  replay.speed = 50.0;
  replay.wait_s = 30.0;
  const live::ReplayResult replayed = live::replay_recording(cell.get(), kRecording, replay);
  EXPECT_EQ(replayed.published, kRecordingSamples);

  const auto seen = health.wait_for(
      "c", [](const status::HealthView& h) { return h.taken >= kRecordingSamples; }, 30s);
  ASSERT_TRUE(seen.has_value()) << cli::testing::read_file(cell_->dir() + "/monitor.log");
  EXPECT_EQ(seen->taken, kRecordingSamples);
  EXPECT_EQ(seen->model_name, "paper");

  // The operator swaps the model in and sees the monitor take it (its health names it).
  const test::LocalDomain operator_domain(kOperatorDomain, cell_->uri("operator-o"));
  const Entity op = operator_domain.participant();
  live::ModelSwapPublisher swaps(op.get(), {"c"});
  status::CellBoard operator_view(op.get(), health_only());
  ASSERT_TRUE(swaps.wait_for_readers(1, 30s));
  swaps.publish("c", cli::testing::read_file(GC_SOURCE_DIR "/data/models/paper.textproto"));
  EXPECT_TRUE(operator_view
                  .wait_for("c",
                            [](const status::HealthView& h) { return h.previous_model_name.has_value(); },
                            30s)
                  .has_value());
}

// Issue 25: the monitor's proposal reaches the operator and a dashboard alike; only the operator
// may apply it (a swap of its text), and the monitor then marks it applied.
TEST_F(LiveRoles, OnlyTheOperatorMayApplyTheMonitorsProposal) {
  const auto monitor = start_monitor({"--diagnose-after-s", "1", "--diagnosis-nice", "0",
                                      "--stale-s", "60", "--dispose-s", "120"});
  const test::LocalDomain cell_domain(kCellDomain, cell_->uri("cell-c"));
  const Entity cell = cell_domain.participant();
  live::ReplayOptions replay;
  replay.test_cell = "c";
  replay.speed = 50.0;
  replay.wait_s = 30.0;
  ASSERT_EQ(live::replay_recording(cell.get(), kRecording, replay).published, kRecordingSamples);

  const test::LocalDomain operator_domain(kOperatorDomain, cell_->uri("operator-o"));
  const Entity op = operator_domain.participant();
  status::MonitorBoard operator_view(op.get());
  const auto proposal = operator_view.wait_for(
      "c", [](const status::v1::ProposalRecord& p) { return p.state() == "standing"; }, 60s);
  ASSERT_TRUE(proposal.has_value()) << cli::testing::read_file(cell_->dir() + "/monitor.log");
  EXPECT_EQ(proposal->effects(), "eccentricity");

  // A dashboard identity reads it, and may not write the swap that would apply it.
  const test::LocalDomain dashboard_domain(kDashboardDomain, cell_->uri("dashboard-main"));
  const Entity dashboard = dashboard_domain.participant();
  status::MonitorBoard dashboard_view(dashboard.get());
  EXPECT_TRUE(dashboard_view
                  .wait_for("c", [&](const auto& p) { return p.proposal_id() == proposal->proposal_id(); }, 30s)
                  .has_value());
  EXPECT_THROW(live::ModelSwapPublisher(dashboard.get(), {"c"}), protocol::DdsError);

  live::ModelSwapPublisher swaps(op.get(), {"c"}, "by=operator-o;source=proposal " + proposal->proposal_id());
  ASSERT_TRUE(swaps.wait_for_readers(1, 30s));
  swaps.publish("c", proposal->model_text());
  const auto applied = operator_view.wait_for(
      "c", [](const status::v1::ProposalRecord& p) { return p.state() == "applied"; }, 30s);
  ASSERT_TRUE(applied.has_value());
  EXPECT_EQ(applied->state(), "applied") << applied->state_reason();
  EXPECT_NE(applied->state_reason().find("operator-o"), std::string::npos) << applied->state_reason();
}

// Issue 25's leftover: who swapped. The writer's USER_DATA "by=" is whatever the swapper says;
// the operator identity the audit trail names beside it comes from the writer's partition
// gearcoupling.live.operator.NAME, which only operator-NAME's grant allows: operator-o may not
// make a swap writer in operator p's partition (its publisher falls back to the cell's partition
// alone), so a swap claiming p is audited with no identity, and o's swap names operator-o
// whatever its USER_DATA claims.
TEST_F(LiveRoles, TheAuditTrailNamesTheOperatorIdentityTheAccessControlAuthenticated) {
  const auto monitor = start_monitor({"--no-diagnosis"});
  const test::LocalDomain operator_domain(kOperatorDomain, cell_->uri("operator-o"));
  const Entity op = operator_domain.participant();

  // The grant: the cell's and its own operator partition together, not another operator's.
  const Entity topic = live::make_model_topic(op.get());
  for (const char* other : {"o", "p"}) {
    const Entity publisher =
        live::make_publisher_in(op.get(), {live::cell_partition("c"), live::operator_partition(other)});
    const dds_entity_t writer = dds_create_writer(publisher.get(), topic.get(), nullptr, nullptr);
    if (writer > 0) dds_delete(writer);
    EXPECT_EQ(writer > 0, std::string(other) == "o") << other << ": " << dds_strretcode(writer);
    if (std::string(other) == "p") {
      EXPECT_EQ(writer, DDS_RETCODE_NOT_ALLOWED_BY_SECURITY);
    }
  }

  const std::string paper = cli::testing::read_file(GC_SOURCE_DIR "/data/models/paper.textproto");
  const std::string downwind = cli::testing::read_file(GC_SOURCE_DIR "/data/models/paper_downwind.textproto");
  live::ModelSwapPublisher as_o(op.get(), {"c"}, "by=mallory@nowhere;source=file paper", "o");
  ASSERT_TRUE(as_o.wait_for_readers(1, 30s));
  as_o.publish("c", paper);
  status::MonitorBoard operator_view(op.get());
  auto swaps_seen = [&](int count) {
    for (int i = 0; i < 300; ++i) {
      for (const auto& m : operator_view.monitors()) {
        if (m.recent_swaps_size() >= count) return m;
      }
      std::this_thread::sleep_for(100ms);
    }
    return status::v1::MonitorRecord{};
  };
  ASSERT_EQ(swaps_seen(1).recent_swaps_size(), 1) << cli::testing::read_file(cell_->dir() + "/monitor.log");
  live::ModelSwapPublisher claiming_p(op.get(), {"c"}, "by=operator-p;source=file downwind", "p");
  ASSERT_TRUE(claiming_p.wait_for_readers(1, 30s));
  claiming_p.publish("c", downwind);
  const status::v1::MonitorRecord m = swaps_seen(2);
  ASSERT_EQ(m.recent_swaps_size(), 2) << cli::testing::read_file(cell_->dir() + "/monitor.log");
  EXPECT_EQ(m.recent_swaps(0).by(), "mallory@nowhere");       // the claim, as given
  EXPECT_EQ(m.recent_swaps(0).operator_identity(), "operator-o");
  EXPECT_EQ(m.recent_swaps(1).by(), "operator-p");            // a claim the grant did not back
  EXPECT_EQ(m.recent_swaps(1).operator_identity(), "");
  EXPECT_EQ(m.recent_swaps(1).model_after(), "paper_downwind");
  EXPECT_TRUE(monitor->running());
}

struct Permission {
  const char* identity;
  int local_domain;
  const char* topic_name;
  TopicMaker topic;
  bool writer;
  bool allowed;
  const char* partition = "gearcoupling.live";
};

constexpr const char* kCellC = "gearcoupling.live.cell.c";
constexpr const char* kCellD = "gearcoupling.live.cell.d";
constexpr const char* kEveryCell = "gearcoupling.live.cell.*";

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
      {"monitor-m", kMonitorDomain, "measurement", live::make_measurement_topic, false, true, kEveryCell},
      {"monitor-m", kMonitorDomain, "model", live::make_model_topic, false, true, kEveryCell},
      {"monitor-m", kMonitorDomain, "measurement", live::make_measurement_topic, true, false},
      {"monitor-m", kMonitorDomain, "model", live::make_model_topic, true, false},
      // The cell publishes and records its own test cell's measurements, nothing else: not in
      // another cell's partition, nor in the shared one (issue 23, finding 4).
      {"cell-c", kCellDomain, "measurement", live::make_measurement_topic, true, true, kCellC},
      {"cell-c", kCellDomain, "measurement", live::make_measurement_topic, false, true, kCellC},
      {"cell-c", kCellDomain, "measurement", live::make_measurement_topic, false, true},
      {"cell-c", kCellDomain, "measurement", live::make_measurement_topic, true, false, kCellD},
      {"cell-c", kCellDomain, "measurement", live::make_measurement_topic, true, false},
      {"cell-c", kCellDomain, "measurement", live::make_measurement_topic, true, false, kEveryCell},
      {"cell-c", kCellDomain, "measurement", live::make_measurement_topic, false, false, kCellD},
      {"cell-c", kCellDomain, "health", live::make_health_topic, true, false},
      {"cell-c", kCellDomain, "model", live::make_model_topic, true, false, kCellC},
      // The operator publishes models of its granted cells (c) only, and reads the health.
      {"operator-o", kOperatorDomain, "model", live::make_model_topic, true, true, kCellC},
      {"operator-o", kOperatorDomain, "model", live::make_model_topic, true, false, kCellD},
      {"operator-o", kOperatorDomain, "model", live::make_model_topic, true, false},
      {"operator-o", kOperatorDomain, "model", live::make_model_topic, true, false, kEveryCell},
      {"operator-o", kOperatorDomain, "health", live::make_health_topic, false, true},
      {"operator-o", kOperatorDomain, "health", live::make_health_topic, true, false},
      {"operator-o", kOperatorDomain, "measurement", live::make_measurement_topic, true, false},
      // Issue 25: the proposals and the monitor's status are the monitor's to publish; dashboards
      // and operators read them.
      {"monitor-m", kMonitorDomain, "proposal", live::make_proposal_topic, true, true},
      {"monitor-m", kMonitorDomain, "monitor", live::make_monitor_status_topic, true, true},
      {"dashboard-main", kDashboardDomain, "proposal", live::make_proposal_topic, false, true},
      {"dashboard-main", kDashboardDomain, "monitor", live::make_monitor_status_topic, false, true},
      {"dashboard-main", kDashboardDomain, "proposal", live::make_proposal_topic, true, false},
      {"operator-o", kOperatorDomain, "proposal", live::make_proposal_topic, false, true},
      {"operator-o", kOperatorDomain, "monitor", live::make_monitor_status_topic, false, true},
      {"operator-o", kOperatorDomain, "proposal", live::make_proposal_topic, true, false},
      {"cell-c", kCellDomain, "proposal", live::make_proposal_topic, true, false},
      {"cell-c", kCellDomain, "monitor", live::make_monitor_status_topic, true, false},
      // A client of the service has no live rights.
      {"client-a", 227, "measurement", live::make_measurement_topic, true, false},
      {"client-a", 227, "health", live::make_health_topic, false, false},
  };
  for (const Permission& p : table) {
    const test::LocalDomain domain(p.local_domain, cell_->uri(p.identity));
    const Entity participant = domain.participant();
    const dds_return_t got = try_live_endpoint(participant.get(), p.topic, p.writer, p.partition);
    EXPECT_EQ(got, p.allowed ? 1 : DDS_RETCODE_NOT_ALLOWED_BY_SECURITY)
        << p.identity << (p.writer ? " writing " : " reading ") << p.topic_name << " in "
        << p.partition;
  }
}

/// A measurement batch of one sample for `test_cell`, written raw by `writer` (a writer in any
/// partition: what a cell identity controls is only which partition it may use).
void write_one_sample(dds_entity_t writer, const std::string& test_cell, std::uint64_t run_id) {
  gearcoupling_Measurement m{};
  m.sequence_number = 1;
  m.time_s = 0.0;
  m.torque_nm = 1.5e6;
  m.misalignment_rad = 0.005;
  gearcoupling_MeasurementBatch batch{};
  std::copy_n(test_cell.c_str(), test_cell.size() + 1, batch.test_cell);
  batch.run_id = run_id;
  batch.samples._buffer = &m;
  batch.samples._length = batch.samples._maximum = 1;
  batch.samples._release = false;
  ASSERT_EQ(dds_write(writer, &batch), DDS_RETCODE_OK);
}

// Issue 23, finding 4: a cell identity speaks only for its own test cell, an operator swaps only
// the cells it is granted, whatever test_cell their samples name.
TEST_F(LiveRoles, ACellCannotPublishAnotherCellsMeasurementsNorAnOperatorSwapAnUngrantedCell) {
  const auto monitor = start_monitor();
  const test::LocalDomain dashboard_domain(kDashboardDomain, cell_->uri("dashboard-main"));
  const Entity dashboard = dashboard_domain.participant();
  status::CellBoard health(dashboard.get(), health_only());
  const test::LocalDomain cell_domain(kCellDomain, cell_->uri("cell-c"));
  const Entity cell = cell_domain.participant();

  // cell-c may not even make a publisher of test cell d's measurements...
  EXPECT_THROW(live::MeasurementPublisher(cell.get(), "d"), protocol::DdsError);
  // ...and what it writes in its own partition naming test cell d is refused by the monitor:
  // d never appears, while c (the positive control, written after) does.
  const Entity topic = live::make_measurement_topic(cell.get());
  const Entity publisher = live::make_cell_publisher(cell.get(), "c");
  const protocol::Qos qos = live::measurement_writer_qos();
  const Entity writer(protocol::check_dds(
      dds_create_writer(publisher.get(), topic.get(), qos.get(), nullptr), "writer"));
  ASSERT_TRUE(live::wait_for_readers(writer.get(), 1, 30s));
  write_one_sample(writer.get(), "d", 11);
  write_one_sample(writer.get(), "c", 12);
  ASSERT_TRUE(health.wait_for("c", [](const status::HealthView&) { return true; }, 30s).has_value())
      << cli::testing::read_file(cell_->dir() + "/monitor.log");
  EXPECT_FALSE(health.wait_for("d", [](const status::HealthView&) { return true; }, 2s).has_value())
      << "the monitor followed test cell d from cell-c's writer";
  const std::string log = cli::testing::read_file(cell_->dir() + "/monitor.log");
  EXPECT_NE(log.find("measurement batch for test cell d refused"), std::string::npos) << log;

  // operator-o (granted c only) may not make a swap publisher for d, and a swap naming d written
  // in c's partition is refused by the monitor; its swap of c is taken.
  const test::LocalDomain operator_domain(kOperatorDomain, cell_->uri("operator-o"));
  const Entity op = operator_domain.participant();
  EXPECT_THROW(live::ModelSwapPublisher(op.get(), {"d"}), protocol::DdsError);
  const Entity model_topic = live::make_model_topic(op.get());
  const Entity op_publisher = live::make_cell_publisher(op.get(), "c");
  const protocol::Qos model_qos = live::model_qos();
  const Entity swap_writer(protocol::check_dds(
      dds_create_writer(op_publisher.get(), model_topic.get(), model_qos.get(), nullptr), "writer"));
  ASSERT_TRUE(live::wait_for_readers(swap_writer.get(), 1, 30s));
  std::string text = cli::testing::read_file(GC_SOURCE_DIR "/data/models/paper.textproto");
  gearcoupling_ModelSwap swap{};
  std::copy_n("d", 2, swap.test_cell);
  swap.model_text = text.data();
  ASSERT_EQ(dds_write(swap_writer.get(), &swap), DDS_RETCODE_OK);
  EXPECT_TRUE(protocol::wait_until(
      [&] {
        return cli::testing::read_file(cell_->dir() + "/monitor.log")
                   .find("model swap for test cell d refused") != std::string::npos;
      },
      std::chrono::steady_clock::now() + 30s))
      << cli::testing::read_file(cell_->dir() + "/monitor.log");
}

// Issue 38, finding 1, under DDS Security: operator-o, granted test cell c only, swapped c to a
// model whose coupling_file was /dev/zero; the monitor read it, died of std::bad_alloc, and with
// it the monitoring of every cell (d too), at each restart while the swap's writer lived. Now
// the swap is refused unread, c keeps its model and says why, and d is followed on.
TEST_F(LiveRoles, AnOperatorsSwapNamingAFileIsRefusedUnreadAndEveryOtherCellStaysFollowed) {
  const auto monitor = start_monitor();
  const test::LocalDomain dashboard_domain(kDashboardDomain, cell_->uri("dashboard-main"));
  const Entity dashboard = dashboard_domain.participant();
  status::CellBoard health(dashboard.get(), health_only());
  const test::LocalDomain c_domain(kCellDomain, cell_->uri("cell-c"));
  const test::LocalDomain d_domain(kCellDDomain, cell_->uri("cell-d"));
  const Entity cell_c = c_domain.participant();
  const Entity cell_d = d_domain.participant();
  const protocol::Qos qos = live::measurement_writer_qos();
  const Entity c_topic = live::make_measurement_topic(cell_c.get());
  const Entity c_publisher = live::make_cell_publisher(cell_c.get(), "c");
  const Entity c_writer(protocol::check_dds(
      dds_create_writer(c_publisher.get(), c_topic.get(), qos.get(), nullptr), "writer c"));
  const Entity d_topic = live::make_measurement_topic(cell_d.get());
  const Entity d_publisher = live::make_cell_publisher(cell_d.get(), "d");
  const Entity d_writer(protocol::check_dds(
      dds_create_writer(d_publisher.get(), d_topic.get(), qos.get(), nullptr), "writer d"));
  ASSERT_TRUE(live::wait_for_readers(c_writer.get(), 1, 30s));
  ASSERT_TRUE(live::wait_for_readers(d_writer.get(), 1, 30s));
  write_one_sample(c_writer.get(), "c", 1);
  write_one_sample(d_writer.get(), "d", 1);
  ASSERT_TRUE(health.wait_for("c", [](const status::HealthView&) { return true; }, 30s).has_value())
      << cli::testing::read_file(cell_->dir() + "/monitor.log");
  ASSERT_TRUE(health.wait_for("d", [](const status::HealthView& h) { return h.taken == 1; }, 30s).has_value());

  const test::LocalDomain operator_domain(kOperatorDomain, cell_->uri("operator-o"));
  const Entity op = operator_domain.participant();
  live::ModelSwapPublisher swaps(op.get(), {"c"});
  ASSERT_TRUE(swaps.wait_for_readers(1, 30s));
  swaps.publish("c", "name: \"zero\"\ncoupling_file: \"/dev/zero\"\n");
  const auto refused = health.wait_for(
      "c", [](const status::HealthView& h) { return !h.last_model_refusal.empty(); }, 30s);
  ASSERT_TRUE(refused.has_value()) << cli::testing::read_file(cell_->dir() + "/monitor.log");
  EXPECT_NE(refused->last_model_refusal.find("model.coupling_file"), std::string::npos)
      << refused->last_model_refusal;
  EXPECT_EQ(refused->model_name, "paper");
  // d, another cell (another identity), is followed on: a new run of it is taken.
  write_one_sample(d_writer.get(), "d", 2);
  EXPECT_TRUE(health.wait_for("d", [](const status::HealthView& h) { return h.taken == 2; }, 30s).has_value())
      << cli::testing::read_file(cell_->dir() + "/monitor.log");
  EXPECT_TRUE(monitor->running()) << cli::testing::read_file(cell_->dir() + "/monitor.log");
}

// Issue 38, finding 7, under DDS Security: cell-c's own writer, in its own partition, sends
// 2,000 batches whose test-cell name has odd bytes: the monitor logged a line for each. Now it
// logs the first and at most a summary a second, and counts them all (MonitorStatus.refusals).
TEST_F(LiveRoles, ACellIdentitysFloodOfBadlyNamedBatchesIsCountedAndBarelyLogged) {
  const auto monitor = start_monitor();
  const test::LocalDomain dashboard_domain(kDashboardDomain, cell_->uri("dashboard-main"));
  const Entity dashboard = dashboard_domain.participant();
  status::MonitorBoard monitors(dashboard.get(), 64);
  const test::LocalDomain c_domain(kCellDomain, cell_->uri("cell-c"));
  const Entity cell_c = c_domain.participant();
  const protocol::Qos qos = live::measurement_writer_qos();
  const Entity topic = live::make_measurement_topic(cell_c.get());
  const Entity publisher = live::make_cell_publisher(cell_c.get(), "c");
  const Entity writer(protocol::check_dds(
      dds_create_writer(publisher.get(), topic.get(), qos.get(), nullptr), "writer c"));
  ASSERT_TRUE(live::wait_for_readers(writer.get(), 1, 30s));
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 2000; ++i) write_one_sample(writer.get(), "\x01\x7f odd\xff", 5);
  std::uint64_t counted = 0;
  protocol::wait_until(
      [&] {
        for (const auto& m : monitors.monitors()) {
          const auto found = m.refusals().find("batch_bad_name");
          if (found != m.refusals().end()) counted = found->second;
        }
        return counted == 2000;
      },
      std::chrono::steady_clock::now() + 30s);
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(counted, 2000u);
  const std::string log = cli::testing::read_file(cell_->dir() + "/monitor.log");
  std::size_t lines = 0;
  for (std::size_t at = log.find("batch_bad_name"); at != std::string::npos; at = log.find("batch_bad_name", at + 1)) ++lines;
  EXPECT_GE(lines, 1u);
  EXPECT_LE(lines, 2u + static_cast<std::size_t>(elapsed_s)) << log.substr(0, 2000);
  EXPECT_TRUE(monitor->running());
}

// Issue 23, finding 5, for the monitor: a cell identity revoked while the monitor runs is cut off
// by SIGHUP (a new participant reads the new CRL); a valid cell's measurements are taken again
// after the interruption.
TEST_F(LiveRoles, ARevokedCellIsCutOffBySighupToTheMonitorWhileAValidCellIsFollowedAgain) {
  using Clock = std::chrono::steady_clock;
  const auto monitor = start_monitor();
  const test::LocalDomain c_domain(kCellDomain, cell_->uri("cell-c"));
  const test::LocalDomain d_domain(227, cell_->uri("cell-d"));
  const Entity c_participant = c_domain.participant();
  const Entity d_participant = d_domain.participant();
  const auto raw_writer = [](dds_entity_t participant, const std::string& test_cell,
                             std::vector<Entity>& keep) {
    keep.push_back(live::make_measurement_topic(participant));
    const dds_entity_t topic = keep.back().get();
    keep.push_back(live::make_cell_publisher(participant, test_cell));
    const protocol::Qos qos = live::measurement_writer_qos();
    keep.emplace_back(protocol::check_dds(
        dds_create_writer(keep.back().get(), topic, qos.get(), nullptr), "writer"));
    return keep.back().get();
  };
  std::vector<Entity> c_entities, d_entities;
  const dds_entity_t c_writer = raw_writer(c_participant.get(), "c", c_entities);
  const dds_entity_t d_writer = raw_writer(d_participant.get(), "d", d_entities);
  ASSERT_TRUE(live::wait_for_readers(c_writer, 1, 30s));
  ASSERT_TRUE(live::wait_for_readers(d_writer, 1, 30s));
  std::uint64_t run = 100;
  write_one_sample(c_writer, "c", ++run);
  write_one_sample(d_writer, "d", ++run);
  {
    const test::LocalDomain dashboard_domain(kDashboardDomain, cell_->uri("dashboard-main"));
    const Entity dashboard = dashboard_domain.participant();
    status::CellBoard health(dashboard.get(), health_only());
    const auto any = [](const status::HealthView&) { return true; };
    ASSERT_TRUE(health.wait_for("c", any, 30s).has_value());
    ASSERT_TRUE(health.wait_for("d", any, 30s).has_value());  // d is followed before
  }

  cell_->rerun("--revoke cell-d");
  const Clock::time_point hup = Clock::now();
  monitor->signal(SIGHUP);
  // The old monitor's reader goes (bounded), then both cells keep publishing.
  EXPECT_TRUE(protocol::wait_until([&] { return protocol::matched_reader_count(c_writer) == 0; },
                                   hup + 10s));
  std::atomic<bool> publishing{true};
  std::thread publisher([&] {
    for (int k = 0; k < 1500 && publishing; ++k) {  // 30 s at most
      write_one_sample(c_writer, "c", 1000 + 2 * static_cast<std::uint64_t>(k));
      write_one_sample(d_writer, "d", 1001 + 2 * static_cast<std::uint64_t>(k));
      std::this_thread::sleep_for(20ms);
    }
  });
  const test::LocalDomain dashboard_domain(kDashboardDomain, cell_->uri("dashboard-main"));
  const Entity dashboard = dashboard_domain.participant();
  status::CellBoard health(dashboard.get(), health_only());
  const auto taken = [](const status::HealthView& h) { return h.taken >= 1; };
  const auto c_again = health.wait_for("c", taken, 30s);
  const double interruption_s = std::chrono::duration<double>(Clock::now() - hup).count();
  const auto d_again = health.wait_for("d", taken, 3s);
  const std::uint32_t d_readers = protocol::matched_reader_count(d_writer);
  publishing = false;
  publisher.join();
  std::printf("monitor SIGHUP: test cell c's health back after %.3f s; revoked cell-d: %s, its "
              "writer matched by %u readers\n",
              interruption_s, d_again ? "FOLLOWED" : "not followed", d_readers);
  EXPECT_TRUE(c_again.has_value()) << cli::testing::read_file(cell_->dir() + "/monitor.log");
  EXPECT_FALSE(d_again.has_value()) << "the new monitor follows the revoked cell-d";
  EXPECT_EQ(d_readers, 0u);
  EXPECT_TRUE(monitor->running());
}

}  // namespace
}  // namespace gc
