// CellBoard against real DDS samples on this test's own loopback domain: residual batches
// written as the monitor writes them are aggregated per drain (count, time span, min/max/mean per
// channel), never kept one by one; the health is copied; staleness is shown.
#include "clients/status/cell_board.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

#include "gearcoupling.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "tests/service/service_process.h"

namespace gc::status {
namespace {

using Clock = std::chrono::steady_clock;

class CellBoardTest : public ::testing::Test {
 protected:
  void SetUp() override {
    test::use_loopback_config();
    participant_ = live::make_participant(test::test_domain());
    publisher_ = live::make_live_publisher(participant_.get());
    residual_topic_ = live::make_residual_topic(participant_.get());
    health_topic_ = live::make_health_topic(participant_.get());
    residual_writer_ = protocol::Entity(protocol::check_dds(
        dds_create_writer(publisher_.get(), residual_topic_.get(), live::residual_qos().get(), nullptr),
        "dds_create_writer(residual)"));
    health_writer_ = protocol::Entity(protocol::check_dds(
        dds_create_writer(publisher_.get(), health_topic_.get(), live::health_writer_qos().get(), nullptr),
        "dds_create_writer(health)"));
  }

  /// Waits (at most 10 s) until `writer` has matched a reader.
  static void wait_matched(dds_entity_t writer) {
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    dds_publication_matched_status_t status{};
    while (Clock::now() < deadline) {
      dds_get_publication_matched_status(writer, &status);
      if (status.current_count > 0) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    FAIL() << "no reader matched";
  }

  void write_residuals(const char* cell, const std::vector<gearcoupling_Residual>& residuals) {
    gearcoupling_ResidualBatch batch{};
    std::strncpy(batch.test_cell, cell, 64);
    batch.run_id = 1;
    batch.model_name = const_cast<char*>("paper");
    batch.decimation = 1;
    batch.published_ns = 1'700'000'000'000'000'000ull;
    batch.residuals._buffer = const_cast<gearcoupling_Residual*>(residuals.data());
    batch.residuals._length = batch.residuals._maximum = static_cast<uint32_t>(residuals.size());
    ASSERT_EQ(dds_write(residual_writer_.get(), &batch), DDS_RETCODE_OK);
  }

  /// Drains `board` until it shows `cell` with `residuals` residuals in all (at most 10 s).
  static std::vector<v1::ResidualAggregate> drain_until(CellBoard& board, const std::string& cell,
                                                        std::uint64_t residuals) {
    std::vector<v1::ResidualAggregate> aggregates;
    std::uint64_t seen = 0;
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    while (seen < residuals && Clock::now() < deadline) {
      for (const auto& record : board.drain()) {
        if (record.test_cell() != cell) continue;
        for (const auto& a : record.residuals()) {
          aggregates.push_back(a);
          seen += a.residuals();
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return aggregates;
  }

  protocol::Entity participant_, publisher_, residual_topic_, health_topic_;
  protocol::Entity residual_writer_, health_writer_;
};

TEST_F(CellBoardTest, ResidualsOfOneIntervalBecomeOneEnvelopePerChannel) {
  CellBoard board(participant_.get());
  wait_matched(residual_writer_.get());
  // Hand-made values: M_sy' measured 10, 20, 60 (min 10, max 60, mean 30); predicted 11, 21, 61.
  write_residuals("dyno-a", {{1, 0.5, 10.0, -1.0, 11.0, -2.0},
                             {2, 0.6, 20.0, -3.0, 21.0, -4.0},
                             {3, 0.7, 60.0, -5.0, 61.0, -6.0}});
  const auto aggregates = drain_until(board, "dyno-a", 3);
  ASSERT_EQ(aggregates.size(), 1u);  // one batch, so one interval
  const v1::ResidualAggregate& a = aggregates[0];
  EXPECT_EQ(a.residuals(), 3u);
  EXPECT_EQ(a.model_name(), "paper");
  EXPECT_DOUBLE_EQ(a.time_begin_s(), 0.5);
  EXPECT_DOUBLE_EQ(a.time_end_s(), 0.7);
  EXPECT_DOUBLE_EQ(a.msy_measured_nm().min(), 10.0);
  EXPECT_DOUBLE_EQ(a.msy_measured_nm().max(), 60.0);
  EXPECT_DOUBLE_EQ(a.msy_measured_nm().mean(), 30.0);
  EXPECT_DOUBLE_EQ(a.msy_predicted_nm().mean(), 31.0);
  EXPECT_DOUBLE_EQ(a.msz_measured_nm().min(), -5.0);
  EXPECT_DOUBLE_EQ(a.msz_predicted_nm().max(), -2.0);
  EXPECT_DOUBLE_EQ(a.latest_published_unix_s(), 1.7e9);
  // Drained: the next update carries no residual until new ones come.
  for (const auto& record : board.drain()) EXPECT_EQ(record.residuals_size(), 0);
}

TEST_F(CellBoardTest, HealthIsCopiedAndAStaleCellShowsStale) {
  CellBoard board(participant_.get());
  wait_matched(health_writer_.get());
  gearcoupling_CellHealth health{};
  std::strncpy(health.test_cell, "dyno-b", 64);
  health.monitor_id = 0xabc;
  health.stale = true;
  health.model.model_name = const_cast<char*>("paper");
  health.model.msy.rmse_nm = 1500.0;
  health.model.msy.noise_nm = 900.0;
  health.worst_region = const_cast<char*>("M_sz' errs most at low torque");
  health.last_refusal = const_cast<char*>("");
  health.last_model_refusal = const_cast<char*>("");
  health.counts.taken = 40000;
  ASSERT_EQ(dds_write(health_writer_.get(), &health), DDS_RETCODE_OK);
  std::vector<v1::TestCellRecord> cells;
  const auto deadline = Clock::now() + std::chrono::seconds(10);
  while (cells.empty() && Clock::now() < deadline) {
    cells = board.snapshot();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(cells.size(), 1u);
  const v1::TestCellRecord& cell = cells[0];
  EXPECT_EQ(cell.test_cell(), "dyno-b");
  EXPECT_EQ(cell.state(), "stale");
  EXPECT_EQ(cell.monitor_id(), "0000000000000abc");
  EXPECT_EQ(cell.model().model_name(), "paper");
  EXPECT_DOUBLE_EQ(cell.model().msy().rmse_nm(), 1500.0);
  EXPECT_DOUBLE_EQ(cell.model().msy().noise_nm(), 900.0);
  EXPECT_EQ(cell.worst_region(), "M_sz' errs most at low torque");
  EXPECT_EQ(cell.counts().taken(), 40000u);
  EXPECT_FALSE(cell.has_previous_model());
}

/// A health sample of `cell` as the monitor writes it, `taken` samples so far.
void write_health(dds_entity_t writer, const char* cell, std::uint64_t taken, const char* model) {
  gearcoupling_CellHealth health{};
  std::strncpy(health.test_cell, cell, 64);
  health.model.model_name = const_cast<char*>(model);
  health.worst_region = const_cast<char*>("");
  health.last_refusal = const_cast<char*>("");
  health.last_model_refusal = const_cast<char*>("");
  health.counts.taken = taken;
  ASSERT_EQ(dds_write(writer, &health), DDS_RETCODE_OK);
}

// Issue 24: the one reader of the health topic also serves swap-model and the live tests, which
// wait for one cell's health to reach a state.
TEST_F(CellBoardTest, WaitForReturnsOnceTheCellsHealthIsReady) {
  CellBoard board(participant_.get());
  wait_matched(health_writer_.get());
  EXPECT_FALSE(board.latest("dyno-w").has_value());
  std::thread writer([this] {
    for (std::uint64_t taken = 100; taken <= 500; taken += 100) {
      write_health(health_writer_.get(), "dyno-w", taken, "paper");
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
  const auto start = Clock::now();
  const auto health = board.wait_for(
      "dyno-w", [](const HealthView& h) { return h.taken >= 300; }, std::chrono::seconds(10));
  writer.join();
  ASSERT_TRUE(health.has_value());
  EXPECT_GE(health->taken, 300u);
  EXPECT_EQ(health->model_name, "paper");
  EXPECT_FALSE(health->stale);
  EXPECT_FALSE(health->disposed);
  EXPECT_LT(Clock::now() - start, std::chrono::seconds(5));
  EXPECT_EQ(board.latest("dyno-w")->taken, 500u);
}

TEST_F(CellBoardTest, WaitForGivesUpAtItsTimeoutWithTheLatestHealth) {
  CellBoard board(participant_.get());
  wait_matched(health_writer_.get());
  write_health(health_writer_.get(), "dyno-t", 7, "paper");
  const auto start = Clock::now();
  const auto health = board.wait_for(
      "dyno-t", [](const HealthView& h) { return h.taken > 1000; }, std::chrono::milliseconds(400));
  const auto waited = Clock::now() - start;
  ASSERT_TRUE(health.has_value());
  EXPECT_EQ(health->taken, 7u);
  EXPECT_GE(waited, std::chrono::milliseconds(390));
  EXPECT_LT(waited, std::chrono::seconds(2));
}

TEST_F(CellBoardTest, AReaderOfOneCellIgnoresTheOthersAndReadsNoResiduals) {
  CellBoardOptions options;
  options.only_cell = "mine";
  options.max_cells = 1;
  options.read_residuals = false;
  CellBoard board(participant_.get(), options);
  wait_matched(health_writer_.get());
  write_health(health_writer_.get(), "other", 1, "paper");  // would take the only place
  write_health(health_writer_.get(), "mine", 2, "paper");
  const auto mine = board.wait_for("mine", [](const HealthView&) { return true; }, std::chrono::seconds(10));
  ASSERT_TRUE(mine.has_value());
  EXPECT_EQ(mine->taken, 2u);
  EXPECT_FALSE(board.latest("other").has_value());
  EXPECT_EQ(board.refused(), 0u);  // ignored, not refused
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  dds_publication_matched_status_t residual_readers{};
  dds_get_publication_matched_status(residual_writer_.get(), &residual_readers);
  EXPECT_EQ(residual_readers.current_count, 0u);  // no residual reader (an operator may not have one)
  write_residuals("mine", {gearcoupling_Residual{}});
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  for (const auto& record : board.drain()) EXPECT_EQ(record.residuals_size(), 0);
}

}  // namespace
}  // namespace gc::status
