// What the monitor refuses, by kind: counted for its status (MonitorStatus.refusals, the
// dashboard's /metrics) and logged so that no sender can flood the log (issue 38, finding 7):
// a kind's first refusal with its reason, then at most one summary a second per kind (how many
// since the last line, and the latest reason). Reasons are shown printable and bounded, whatever
// bytes a sample carried.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

namespace gc::live {

enum class Refusal {
  batch_bad_name,          ///< a measurement batch whose test_cell is no test cell name
  batch_oversized,         ///< more samples than kMaxBatchSamples in one batch
  batch_foreign,           ///< written from another test cell's partition
  batch_beyond_max_cells,  ///< a new test cell while --max-cells are followed
  swap_bad_name,           ///< a model swap whose test_cell is no test cell name
  swap_foreign,            ///< a model swap written from another test cell's partition
  swap_no_room,            ///< a swap for a cell not followed, none of the kept ones could go
  swap_bad_model,          ///< a model text refused (syntax, bounds, a file named, the physics)
};
inline constexpr std::size_t kRefusalKinds = 8;

/// "batch_bad_name", ...: the kind as MonitorStatus and /metrics name it.
const char* refusal_kind(Refusal kind);

/// `text` with every byte outside printable ASCII as \xNN, cut to `most` bytes (then "..."):
/// what a refusal may quote of a sample in a log line or a status field.
std::string printable(std::string_view text, std::size_t most = 256);

class RefusalLog {
 public:
  using Clock = std::chrono::steady_clock;
  explicit RefusalLog(Clock::duration summary_every = std::chrono::seconds(1))
      : summary_every_(summary_every) {}

  /// Counts one refusal of `kind` (with its `samples`, for batches) and logs it at warning
  /// level when it is the kind's first, or as a summary when the kind's last line is
  /// summary_every old. Returns whether it logged.
  bool refuse(Refusal kind, std::string_view reason, std::uint64_t samples = 0,
              Clock::time_point now = Clock::now());
  /// Logs the summary of every kind refused since its last line, once that line is
  /// summary_every old: so the last refusals of a burst are told too (the monitor calls it
  /// each health period).
  void flush(Clock::time_point now = Clock::now());

  std::uint64_t count(Refusal kind) const { return kinds_[index(kind)].count; }
  std::uint64_t samples(Refusal kind) const { return kinds_[index(kind)].samples; }
  /// Log lines written (first refusals and summaries).
  std::uint64_t lines() const { return lines_; }

 private:
  struct Kind {
    std::uint64_t count = 0, samples = 0;
    std::uint64_t count_at_last_line = 0;
    Clock::time_point last_line{};
    std::string latest;   // the latest reason, printable()
  };
  static std::size_t index(Refusal kind) { return static_cast<std::size_t>(kind); }
  void summarise(Refusal kind, Kind& k, Clock::time_point now);

  Clock::duration summary_every_;
  std::array<Kind, kRefusalKinds> kinds_{};
  std::uint64_t lines_ = 0;
};

}  // namespace gc::live
