// The monitor's audit trail of model swaps: who put which model in force for which test cell,
// when, from which proposal or file, and the error before and after. The latest kKept are kept
// in memory (every swap is also logged) and published in the monitor's status
// (live/monitor_status_wire.h); with a state directory every swap is also appended to a file
// there and the trail is loaded from it at start, so a restart does not forget it
// (live/swap_audit_file.h).
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <string>

#include "live/cell_monitor.h"

namespace gc::live {

struct SwapEntry {
  std::uint64_t id = 0;                    ///< random, never 0: names the record on disk
  std::string test_cell;
  std::chrono::system_clock::time_point at;
  std::string by, source;                  ///< the swapper's claim (its writer's USER_DATA)
  /// "operator-NAME" when the swap's writer was in partition gearcoupling.live.operator.NAME:
  /// under DDS Security only that identity's grant allows it (docs/security.md); "" otherwise.
  std::string operator_identity;
  std::uint64_t proposal_id = 0;
  std::string model_before, model_after;
  double before_rmse_nm[2] = {0.0, 0.0};   ///< M_sy', M_sz' [N·m]
  double after_rmse_nm[2] = {0.0, 0.0};
  std::uint64_t after_samples = 0;
  bool after_frozen = false;               ///< the model was replaced, or the cell is gone
  /// The ModelSwap sample: its writer's GUID (32 hex digits) and its source timestamp [ns since
  /// 1970]. A restarted monitor gets the latest swap of every live swap writer again
  /// (TRANSIENT_LOCAL); these tell it that swap is already in the trail.
  std::string writer;
  std::int64_t written_ns = 0;
};

class SwapAuditFile;

class SwapAudit {
 public:
  static constexpr std::size_t kKept = 64;

  /// In memory only.
  SwapAudit();
  /// Also on disk in `state_dir` (live/swap_audit_file.h), "" for memory only: the latest kKept
  /// swaps are loaded from it (a damaged line logged and skipped). Throws InvalidInput naming
  /// "--state-dir" when the directory does not exist or its file cannot be opened.
  explicit SwapAudit(const std::filesystem::path& state_dir);
  ~SwapAudit();

  /// Records a swap for `test_cell` (and appends it to the file); the cell's earlier swap, if
  /// any, stops following the health.
  void add(SwapEntry entry);
  /// Whether the swap sample (`writer`, `written_ns`) is in the trail already: given again by
  /// its TRANSIENT_LOCAL writer to a restarted monitor.
  bool contains(const std::string& writer, std::int64_t written_ns) const;
  /// Updates the after-figures of `test_cell`'s latest swap from its health, while its model is
  /// the one that swap put in force.
  void follow(const std::string& test_cell, const HealthReport& health);
  /// `test_cell` is gone: its latest swap's after-figures stay as they are (and are written to
  /// the file).
  void freeze(const std::string& test_cell);
  /// The monitor stops: every swap's after-figures as they are now go to the file.
  void close();

  const std::deque<SwapEntry>& entries() const { return entries_; }
  /// Swaps added since this trail was made (not those loaded).
  std::uint64_t total() const { return total_; }

 private:
  SwapEntry* latest(const std::string& test_cell);
  void freeze(SwapEntry& entry);

  std::deque<SwapEntry> entries_;
  std::uint64_t total_ = 0;
  std::unique_ptr<SwapAuditFile> file_;
};

}  // namespace gc::live
