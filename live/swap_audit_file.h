// The audit trail of model swaps on disk, so that a restart of the monitor (a kill, a crash, a
// reboot, a new package) does not forget who put which model in force (docs/architecture.md,
// "The audit trail on disk"). Append-only: one line per record in <state dir>/swap_audit.log,
// each line written whole by one write() and flushed by fdatasync() before the swap is
// published, so a kill leaves at most one torn last line, which the next load cuts off.
//
// A line is `v1 HASH KIND FIELDS...`, HASH the FNV-1a 64 of what follows it in 16 hex digits:
// it tells a damaged line (a bad disk block, an editor) from a record, not a forged one from a
// true one (the file is the monitor's own, 0640 in a 0750 directory of its user). KIND is
//   swap  ID AT_NS TEST_CELL PROPOSAL_ID BEFORE_MSY BEFORE_MSZ AFTER_MSY AFTER_MSZ AFTER_SAMPLES
//         WRITER WRITTEN_NS BY SOURCE MODEL_BEFORE MODEL_AFTER OPERATOR_IDENTITY
//   after ID AFTER_MSY AFTER_MSZ AFTER_SAMPLES STATE
// with ID and PROPOSAL_ID in 16 hex digits, times in ns since 1970 (UTC), RMSE in N·m, texts
// percent-encoded (space, '%', control bytes; "-" is empty). An `after` line replaces the
// after-figures of the swap of its ID (the latest line wins, one entry per ID). STATE is
// `following` for the figures written while the swap's model is in force (SwapAudit::follow, at a
// bounded rate, by write() alone: a kill of the monitor does not lose what the kernel has), and
// `final` when it stops following it (another swap of the cell, the cell gone, the monitor
// stopping; flushed by fdatasync). A swap loaded without a `final` line was cut off by a kill:
// its figures are the last written and it is marked SwapEntry::after_interrupted. (An `after`
// line without STATE is an older monitor's, which wrote one only at the end: final.)
//
// Bounded, and fair between test cells (issue 38, finding 3): every text field of a line is
// cut to kMaxFieldBytes once encoded, so a line is at most kMaxLineBytes (2 KiB) whatever the
// names. When a record would take the file beyond the rotation bound (kRotateBytes, 1 MiB), the
// records of swap_audit.log.1 and swap_audit.log are compacted into a new swap_audit.log.1 of at
// most the bound: first the latest kKeptPerCell (8) swaps of every test cell, cells with the most
// recent swap first, then, in the room left, the most recent other swaps; a new file is started.
// So the two files stay within 2 kRotateBytes (2 MiB), and one cell's swaps, however many or
// long, never push another cell's latest 8 out: that holds for every test cell while 8 lines of
// each fit the bound, at least 64 cells (1 MiB / (8 x 2 KiB)), about 400 cells with names of
// ordinary length (lines of 300 bytes). Beyond that the cells swapped longest ago go whole, and
// the rotation logs it. The swaps still followed are written again at the head of the new file
// (carry()): a `swap` line whose ID is already loaded replaces that entry, so a model in force
// for months keeps its record.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "live/swap_audit.h"

namespace gc::live {

/// Whether an `after` line is written while its swap is followed, or when it stops.
enum class AfterState { following, final };

class SwapAuditFile {
 public:
  /// 1 MiB: 4,000 swaps of 250 bytes each, years of a test hall's approvals, read in
  /// milliseconds at start.
  static constexpr std::uintmax_t kRotateBytes = 1u << 20;
  /// A text field of a line (by, source, model names, ...) once percent-encoded, at most; and
  /// so a whole line.
  static constexpr std::size_t kMaxFieldBytes = 240;
  static constexpr std::size_t kMaxLineBytes = 2048;
  /// Swaps of each test cell a rotation keeps at least (the latest).
  static constexpr std::size_t kKeptPerCell = 8;

  /// Opens (creates, 0640) `state_dir`/swap_audit.log for appending. Throws InvalidInput
  /// naming "--state-dir" when the directory does not exist or the file cannot be opened.
  /// `rotate_bytes`: kRotateBytes but in tests.
  explicit SwapAuditFile(std::filesystem::path state_dir, std::uintmax_t rotate_bytes = kRotateBytes);
  ~SwapAuditFile();
  SwapAuditFile(const SwapAuditFile&) = delete;
  SwapAuditFile& operator=(const SwapAuditFile&) = delete;

  /// `keep` swaps of swap_audit.log.1 then swap_audit.log (the latest, a cell of many giving up
  /// its oldest first: fair_evictee), oldest first (by AT), each
  /// with its latest after-figures and frozen (the monitor that followed them is gone), marked
  /// after_interrupted when no `final` after line closed it. A line that
  /// does not parse is logged as an error (file, line, why) and skipped; a torn last line (no
  /// end of line: a write cut off) is logged and cut off the file.
  std::vector<SwapEntry> load(std::size_t keep);
  /// Appends a swap and flushes it to the disk (fdatasync). A failure (disk full, the file
  /// removed) is logged as an error, never thrown: the monitor serves on. Returns whether the
  /// file was rotated first: the caller then carries the swaps it still follows (carry()).
  bool append_swap(const SwapEntry& entry);
  /// Appends the after-figures of a swap, flushed to the disk when `flush`: a `following` line
  /// is not (it outlives a kill of the process, not a power cut of the host), a `final` one is,
  /// unless a swap line, whose fdatasync flushes it too, is appended right after it. As
  /// append_swap.
  bool append_after(const SwapEntry& entry, AfterState state, bool flush);
  /// Writes the swap lines of `followed` at the head of a file just rotated, flushed, as far as
  /// they fit in half of kRotateBytes (a swap left out is logged).
  void carry(const std::vector<const SwapEntry*>& followed);

  const std::filesystem::path& path() const { return path_; }

 private:
  bool append(const std::string& payload, bool flush);
  void write_out(const std::string& lines, bool flush, const std::string& what);
  void open_for_append();
  void rotate();
  /// The compacted records of both files into swap_audit.log.1 (see the top); false when it
  /// could not be written (then the old file is renamed whole, as before).
  bool compact_into_rotated();

  std::filesystem::path dir_, path_;
  std::uintmax_t rotate_bytes_;
  int fd_ = -1;
  std::uintmax_t size_ = 0;
};

/// One line's payload (what follows HASH) for a swap, or for its after-figures; each text field
/// at most kMaxFieldBytes encoded (cut, with "..." at its end). Exposed for the tests, which
/// write damaged files.
std::string swap_record_payload(const SwapEntry& entry);
std::string after_record_payload(const SwapEntry& entry, AfterState state);
/// `v1 HASH payload` for `payload`.
std::string audit_line(const std::string& payload);

}  // namespace gc::live
