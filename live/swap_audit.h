// The monitor's audit trail of model swaps: who put which model in force for which test cell,
// when, from which proposal or file, and the error before and after. kKept are kept in memory
// (the latest, but each cell's latest before another cell's older ones: fair_evictee) (every swap is also logged) and published in the monitor's status
// (live/monitor_status_wire.h); with a state directory every swap, and the after-figures it is
// followed by, are also appended to a file there and the trail is loaded from it at start, so a
// restart does not forget it (live/swap_audit_file.h).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
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
  /// Loaded from the file: the monitor that followed the swap stopped without writing its final
  /// after-figures (killed, crashed, the power cut), so they are the last it wrote, not the
  /// whole stay of the model in force.
  bool after_interrupted = false;
  /// The ModelSwap sample: its writer's GUID (32 hex digits) and its source timestamp [ns since
  /// 1970]. A restarted monitor gets the latest swap of every live swap writer again
  /// (TRANSIENT_LOCAL); these tell it that swap is already in the trail.
  std::string writer;
  std::int64_t written_ns = 0;
};

/// "following" (its model is in force, the figures still updated), "final" (it stopped following:
/// the next swap of the cell, the cell gone, the monitor stopped) or "interrupted" (loaded after
/// a kill: the figures are the last written, not complete): SwapRecord.after_state.
const char* after_state_text(const SwapEntry& entry);

/// Which of `entries` (oldest first, not empty) leaves a full trail: the oldest swap of the test
/// cell with the most swaps in it, so that one cell's swaps, however many, never push another
/// cell's latest out of the trail (issue 38) while it holds fewer cells than entries.
template <typename Entries>
std::size_t fair_evictee(const Entries& entries) {
  std::map<std::string, std::size_t> counts;
  for (const auto& e : entries) ++counts[e.test_cell];
  std::size_t most = 0;
  for (const auto& [cell, count] : counts) most = std::max(most, count);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (counts[entries[i].test_cell] == most) return i;
  }
  return 0;
}

class SwapAuditFile;

class SwapAudit {
 public:
  static constexpr std::size_t kKept = 64;
  /// The after-figures of a swap still followed are written at its first health with samples,
  /// then 1 s, 2 s, 4 s ... later, at most every 10 min, each time only if they changed. A kill
  /// loses the figures of at most half the time since the swap while the new model's window
  /// fills (the first minutes, when they move most), at most 10 min of them after; the cost is
  /// about 155 lines of 75 bytes (11 kB) a day per followed test cell, so the file's bound
  /// (SwapAuditFile::kRotateBytes) holds about 90 such days besides the swaps themselves.
  static constexpr std::chrono::seconds kFirstFollowWrite{1};
  static constexpr std::chrono::seconds kMaxFollowWrite{600};

  /// In memory only.
  SwapAudit();
  /// Also on disk in `state_dir` (live/swap_audit_file.h), "" for memory only: the latest kKept
  /// swaps are loaded from it (a damaged line logged and skipped). Throws InvalidInput naming
  /// "--state-dir" when the directory does not exist or its file cannot be opened.
  explicit SwapAudit(const std::filesystem::path& state_dir);
  /// The same with the file rotated at `rotate_bytes` (SwapAuditFile::kRotateBytes but in tests).
  SwapAudit(const std::filesystem::path& state_dir, std::uintmax_t rotate_bytes);
  ~SwapAudit();

  /// Records a swap for `test_cell` (and appends it to the file); the cell's earlier swap, if
  /// any, stops following the health.
  void add(SwapEntry entry);
  /// Whether the swap sample (`writer`, `written_ns`) is in the trail already: given again by
  /// its TRANSIENT_LOCAL writer to a restarted monitor.
  bool contains(const std::string& writer, std::int64_t written_ns) const;
  /// Updates the after-figures of `test_cell`'s latest swap from its health, while its model is
  /// the one that swap put in force; with a file, the figures go to it at a bounded rate
  /// (kFirstFollowWrite, doubling up to kMaxFollowWrite, and only when they changed), so a kill
  /// loses at most that interval of them.
  void follow(const std::string& test_cell, const HealthReport& health,
              std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());
  /// `test_cell` is gone: its latest swap's after-figures stay as they are (and are written to
  /// the file).
  void freeze(const std::string& test_cell);
  /// The monitor stops: every swap's after-figures as they are now go to the file.
  void close();

  const std::deque<SwapEntry>& entries() const { return entries_; }
  /// Swaps added since this trail was made (not those loaded).
  std::uint64_t total() const { return total_; }

 private:
  /// When the after-figures of the swap still followed were last written, and the next wait.
  struct FollowWrites {
    std::chrono::steady_clock::time_point next;
    std::chrono::steady_clock::duration interval{};
    double rmse_nm[2] = {0.0, 0.0};
    std::uint64_t samples = 0;
  };

  SwapEntry* latest(const std::string& test_cell);
  /// Its final after line flushed when `flush`, not when a swap line follows it at once.
  void freeze(SwapEntry& entry, bool flush);
  /// After the file rotated: the swaps still followed are written again at the head of the new
  /// file, so their records are not dropped with it at the next rotation.
  void carry_followed_swaps();

  std::deque<SwapEntry> entries_;
  std::uint64_t total_ = 0;
  std::unique_ptr<SwapAuditFile> file_;
  std::map<std::uint64_t, FollowWrites> follow_writes_;   // by SwapEntry::id, while followed
};

}  // namespace gc::live
