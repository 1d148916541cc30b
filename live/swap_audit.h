// The monitor's audit trail of model swaps: who put which model in force for which test cell,
// when, from which proposal or file, and the error before and after. The latest kKept are kept
// (every swap is also logged); published in the monitor's status (live/monitor_status_wire.h).
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <string>

#include "live/cell_monitor.h"

namespace gc::live {

struct SwapEntry {
  std::string test_cell;
  std::chrono::system_clock::time_point at;
  std::string by, source;
  std::uint64_t proposal_id = 0;
  std::string model_before, model_after;
  double before_rmse_nm[2] = {0.0, 0.0};   ///< M_sy', M_sz' [N·m]
  double after_rmse_nm[2] = {0.0, 0.0};
  std::uint64_t after_samples = 0;
  bool after_frozen = false;               ///< the model was replaced, or the cell is gone
};

class SwapAudit {
 public:
  static constexpr std::size_t kKept = 64;

  /// Records a swap for `test_cell`; the cell's earlier swap, if any, stops following the health.
  void add(SwapEntry entry);
  /// Updates the after-figures of `test_cell`'s latest swap from its health, while its model is
  /// the one that swap put in force.
  void follow(const std::string& test_cell, const HealthReport& health);
  /// `test_cell` is gone: its latest swap's after-figures stay as they are.
  void freeze(const std::string& test_cell);

  const std::deque<SwapEntry>& entries() const { return entries_; }
  std::uint64_t total() const { return total_; }

 private:
  SwapEntry* latest(const std::string& test_cell);

  std::deque<SwapEntry> entries_;
  std::uint64_t total_ = 0;
};

}  // namespace gc::live
