// `gearcoupling record`: captures a live test cell's measurements in the recording format
// (docs/recordings.md), so `validate` and `diagnose` run on the capture unchanged.
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/recorded_sample.h"

namespace gc::live {

struct RecordOptions {
  std::string test_cell;
  double seconds = 10.0;   ///< how long to record, from the start [s]
};

struct Capture {
  std::vector<RecordedSample> samples;   ///< in arrival order
  std::uint64_t refused = 0;             ///< samples with a non-finite member, not written
  std::uint64_t runs = 0;                ///< runs seen (time restarts with each)
  std::string first_refusal;
};

/// Reads test cell `test_cell`'s measurements on `participant` (RELIABLE, KEEP_ALL: nothing
/// lost) for `seconds`. Throws InvalidInput naming "test_cell" or "record.seconds".
Capture capture_measurements(dds_entity_t participant, const RecordOptions& options);

/// The capture as a recording (analysis/recording_csv.h): header and one row per sample.
std::string capture_csv(const Capture& capture);

}  // namespace gc::live
