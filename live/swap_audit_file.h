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
//   after ID AFTER_MSY AFTER_MSZ AFTER_SAMPLES
// with ID and PROPOSAL_ID in 16 hex digits, times in ns since 1970 (UTC), RMSE in N·m, texts
// percent-encoded (space, '%', control bytes; "-" is empty). An `after` line updates the
// after-figures of an earlier swap: written when the swap stops following its model (another
// swap of the cell, the cell gone) and when the monitor stops; a kill loses those of the swaps
// still in force (the load shows them as they were last written).
//
// Bounded: when a record would take the file beyond kRotateBytes, it is renamed
// swap_audit.log.1 (the previous .1 dropped) and a new one started; at most 2 kRotateBytes on
// disk, about 8,000 swaps.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "live/swap_audit.h"

namespace gc::live {

class SwapAuditFile {
 public:
  /// 1 MiB: 4,000 swaps of 250 bytes each, years of a test hall's approvals, read in
  /// milliseconds at start.
  static constexpr std::uintmax_t kRotateBytes = 1u << 20;

  /// Opens (creates, 0640) `state_dir`/swap_audit.log for appending. Throws InvalidInput
  /// naming "--state-dir" when the directory does not exist or the file cannot be opened.
  explicit SwapAuditFile(std::filesystem::path state_dir);
  ~SwapAuditFile();
  SwapAuditFile(const SwapAuditFile&) = delete;
  SwapAuditFile& operator=(const SwapAuditFile&) = delete;

  /// The latest `keep` swaps of swap_audit.log.1 then swap_audit.log, oldest first, each with
  /// its latest after-figures and frozen (the monitor that followed them is gone). A line that
  /// does not parse is logged as an error (file, line, why) and skipped; a torn last line (no
  /// end of line: a write cut off) is logged and cut off the file.
  std::vector<SwapEntry> load(std::size_t keep);
  /// Appends a swap, or the after-figures of one, and flushes it to the disk. A failure (disk
  /// full, the file removed) is logged as an error, never thrown: the monitor serves on.
  void append_swap(const SwapEntry& entry);
  void append_after(const SwapEntry& entry);

  const std::filesystem::path& path() const { return path_; }

 private:
  void append(const std::string& payload);
  void open_for_append();
  void rotate();

  std::filesystem::path dir_, path_;
  int fd_ = -1;
  std::uintmax_t size_ = 0;
};

/// One line's payload (what follows HASH) for a swap, or for its after-figures. Exposed for the
/// tests, which write damaged files.
std::string swap_record_payload(const SwapEntry& entry);
std::string after_record_payload(const SwapEntry& entry);
/// `v1 HASH payload` for `payload`.
std::string audit_line(const std::string& payload);

}  // namespace gc::live
