// What the learning loop is doing for one test cell, and what it waits for, in words an operator
// can act on (issue 39): a cell that stays beyond the noise gets a diagnosis within a bounded
// time or one of these reasons, on the page, in `status` and in /metrics. Before it, a 50 Hz
// cell stayed far off for minutes and the monitor said nothing: its 10 s health window held
// 250-500 samples and the loop wanted 400 of them there to judge at all.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace gc::live {

/// Samples the health window must hold before its error is told from the noise: the noise
/// estimate from successive errors needs a few dozen. A count, not a duration, so it holds at
/// every rate; the diagnosis' own minimum (min_diagnosis_samples) is counted over the rolling
/// window, which spans as long as it must.
inline constexpr std::uint64_t kSamplesToJudge = 50;

/// The --window-s that holds kSamplesToJudge samples at `rate_hz` (the reported window spans at
/// least half of it), rounded up to 1, 2 or 5 times a power of ten [s].
double window_to_judge_s(double rate_hz);

struct LearningInputs {
  bool enabled = true;
  bool stale = false;
  double sample_rate_hz = 0.0;          ///< over the health window; 0 when not known yet [Hz]
  double window_s = 10.0;               ///< --window-s [s]
  std::uint64_t window_samples = 0;     ///< in the health window
  bool beyond_noise = false;            ///< judged so (enough samples, a channel beyond)
  double beyond_noise_for_s = 0.0;      ///< [s]
  double diagnose_after_s = 10.0;       ///< [s]
  std::size_t rolling_samples = 0;      ///< in the diagnosis' rolling window
  std::size_t samples_needed = 400;     ///< a diagnosis needs at least
  bool diagnosis_queued = false, diagnosis_running = false, queue_full = false;
  std::optional<std::string> standing_proposal;   ///< its id, 16 hex digits
  std::optional<std::string> found_nothing;       ///< the last diagnosis' note, when it found nothing
  double next_diagnosis_in_s = 0.0;     ///< --rediagnose-s left after the last diagnosis [s]
};

struct LearningStatus {
  /// off, no_samples, at_noise_level, gathering, too_few_samples_in_window, beyond_noise,
  /// waiting_for_samples, diagnosis_queued, diagnosis_running, queue_full, proposed,
  /// found_nothing (the metric's label values; docs/dashboard.md).
  std::string state;
  std::string text;                     ///< the same in words, with what it waits for
  std::uint64_t samples_missing = 0;    ///< before a diagnosis can run (waiting_for_samples)
};

LearningStatus learning_status(const LearningInputs& in);

}  // namespace gc::live
