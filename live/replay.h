// `gearcoupling replay`: publishes a recording as a live test cell would (MeasurementBatch, one
// run), at a sample rate or at a multiple of the recording's own pace, so the whole live chain
// runs without a rig.
#pragma once

#include <dds/dds.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "analysis/recording_csv.h"

namespace gc::live {

struct ReplayOptions {
  std::string test_cell;
  std::optional<double> rate_hz;   ///< samples per second [Hz]; or
  std::optional<double> speed;     ///< times the recording's own pace [-]
  std::size_t max_batch = 64;      ///< most samples per MeasurementBatch (those already due)
  std::uint32_t wait_for_readers = 1;   ///< matched readers to wait for before the first sample
  double wait_s = 10.0;            ///< at most this long [s]
  analysis::RecordingOptions recording;
};

struct ReplayResult {
  std::uint64_t run_id = 0;
  std::uint64_t published = 0;     ///< samples published
  std::size_t excluded_rows = 0;   ///< malformed rows of the file, not published
  double seconds = 0.0;            ///< wall time from first to last sample [s]
};

/// Publishes the recording at `path` on `participant`. Throws InvalidInput for a bad recording,
/// test cell or pace ("replay.rate", "replay.speed").
ReplayResult replay_recording(dds_entity_t participant, const std::filesystem::path& path,
                              const ReplayOptions& options);

}  // namespace gc::live
