// The test cells of a domain as the live monitor reports them (gearcoupling/live/health and
// .../residual, docs/protocol.md "The live test cell"): each cell's latest health with its
// liveness, and its residuals aggregated per interval (min/max/mean per channel), never kept
// sample by sample. The one reader of the health topic: what the dashboard, its /metrics,
// `gearcoupling status` and `swap-model`, the live tests and benchmarks read (latest() and
// wait_for() give one cell's health as a HealthView). Read-only.
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "clients/status/health_view.h"
#include "idl/live_status.pb.h"
#include "protocol/dds_entity.h"

namespace gc::status {

namespace v1 = ::gearcoupling::v1;

struct CellBoardOptions {
  /// A cell whose health (1 Hz) is older than this is stale, whatever the last one said.
  std::chrono::milliseconds stale_after{3000};
  /// A cell gone (disposed) or stale for this long is dropped from the board.
  std::chrono::milliseconds forget_after{std::chrono::minutes(10)};
  /// Cells on the board at most. A new cell beyond it takes the place of the gone or stale one
  /// heard from longest ago, else it is refused (counted in refused(), logged once): whoever
  /// may publish health or residuals cannot grow the board, its JSON or /metrics without bound,
  /// whatever forget_after is. A cell costs the dashboard 5.7 kB resident (its record, strings
  /// cut at kMaxTextBytes, its aggregate, Cyclone's instances), ~650 B of each update's JSON and
  /// about 1.5 kB of /metrics (docs/dashboard.md, "Bounds"): 64, a test hall, keep all small.
  std::size_t max_cells = 64;
  /// Read the residual topic too (the aggregates of drain()). Off for a reader of the health
  /// alone (swap-model under an operator identity, whose permissions grant the health topic
  /// but not the residuals).
  bool read_residuals = true;
  /// Follow this test cell only, ignoring (not counting) every other; "": every cell. What a
  /// reader of one cell's health sets, so that max_cells other cells cannot crowd it out.
  std::string only_cell;
};

/// The longest text (model name, worst region, refusal) a cell keeps from a health sample [bytes];
/// longer ones are cut: the monitor writes sentences, not pages.
inline constexpr std::size_t kMaxTextBytes = 1024;

/// A string of a DDS sample, cut at `max` bytes (the IDL does not bound them); "" for null.
std::string sample_text(const char* value, std::size_t max = kMaxTextBytes);

class CellBoard {
 public:
  using Clock = std::chrono::steady_clock;

  /// Reads health and residuals on `participant` (which must outlive the board). Throws
  /// protocol::DdsError.
  explicit CellBoard(dds_entity_t participant, CellBoardOptions options = {});
  CellBoard(const CellBoard&) = delete;
  CellBoard& operator=(const CellBoard&) = delete;

  /// Every cell with its latest health, state ("alive", "stale", "gone") and health age;
  /// no residuals. Ordered by name.
  std::vector<v1::TestCellRecord> snapshot();
  /// snapshot() with each cell's residual aggregate since the previous drain() (none when no
  /// residual came), which it then forgets: one reader (the dashboard's publisher) drains.
  std::vector<v1::TestCellRecord> drain();
  /// Health samples and residual batches ignored because max_cells cells were on the board.
  std::uint64_t refused();
  /// Cells on the board now.
  std::size_t size();

  /// `test_cell`'s latest health with its state; nullopt before its first health sample.
  std::optional<HealthView> latest(const std::string& test_cell);
  /// Waits, woken by each health sample, until `ready` holds for test_cell's latest health or
  /// `timeout` passes; returns the latest health either way (nullopt: none came). `ready` runs
  /// under the board's lock: keep it to a test of the view.
  std::optional<HealthView> wait_for(const std::string& test_cell,
                                     const std::function<bool(const HealthView&)>& ready,
                                     std::chrono::milliseconds timeout);

 private:
  /// Running min/max/sum of one quantity.
  struct Accumulator {
    double min = 0.0, max = 0.0, sum = 0.0;
    void add(double value, bool first);
    v1::Envelope envelope(std::uint64_t count) const;
  };
  struct Aggregate {
    std::uint64_t count = 0;
    double time_begin_s = 0.0, time_end_s = 0.0;
    std::string model_name;
    Accumulator msy_measured, msy_predicted, msz_measured, msz_predicted;
    std::uint64_t latest_published_ns = 0;
  };
  struct Entry {
    v1::TestCellRecord record;        ///< health fields as the latest health sample gave them
    bool has_health = false;
    bool monitor_says_stale = false;
    bool disposed = false;
    bool writer_lost = false;         ///< the monitor's liveliness lapsed
    Clock::time_point health_received{};
    Clock::time_point last_heard = Clock::now();  ///< health or residual
    Aggregate aggregate;
    std::optional<dds_instance_handle_t> health_handle;   ///< its key in health_handles_
  };

  void take_health();
  void take_residuals();
  std::vector<v1::TestCellRecord> collect(bool drain);
  /// The record of `cell` as snapshot() gives it, if it has health. Call with mutex_ held.
  std::optional<v1::TestCellRecord> health_record_locked(const std::string& cell,
                                                         Clock::time_point now) const;
  /// "alive", "stale" or "gone".
  const char* state_of(const Entry& entry, Clock::time_point now) const;
  /// `cell`'s entry, made when new if there is room (or a gone or stale cell to drop for it);
  /// nullptr, counted and logged once, when not. Call with mutex_ held.
  Entry* admit(const std::string& cell, Clock::time_point now);
  /// Drops an entry and its health handle. Call with mutex_ held.
  std::map<std::string, Entry>::iterator forget(std::map<std::string, Entry>::iterator it);

  CellBoardOptions options_;
  std::mutex mutex_;
  std::condition_variable health_arrived_;  // notified after each batch of health samples
  std::map<std::string, Entry> entries_;
  std::map<dds_instance_handle_t, std::string> health_handles_;   // of the cells on the board
  std::uint64_t refused_ = 0;
  protocol::Entity health_topic_;
  protocol::Entity residual_topic_;
  protocol::Entity subscriber_;
  protocol::Entity health_reader_;    // readers last: deleted first, before what they touch
  protocol::Entity residual_reader_;
};

}  // namespace gc::status
