// A test's own live test cell: the bundled recording's samples published again and again (time
// running on), at a rate, from the test process.
#pragma once

#include <chrono>
#include <thread>
#include <vector>

#include "analysis/recording_csv.h"
#include "live/measurement_publisher.h"

namespace gc::test {

inline std::vector<RecordedSample> paper_samples() {
  return analysis::read_recording(GC_SOURCE_DIR "/data/recordings/paper_torque_ramp.csv").samples;
}

/// Publishes `count` samples at `rate_hz` through `publisher`, cycling through `samples` with
/// the time running on (a recording of 10 s is followed by itself from 10 s). Batches of what
/// is due each millisecond. Returns the count published.
inline std::uint64_t publish_stream(live::MeasurementPublisher& publisher,
                                    const std::vector<RecordedSample>& samples,
                                    std::uint64_t count, double rate_hz,
                                    std::uint64_t first_index = 0) {
  const double period_s = samples.back().input.time_s - samples.front().input.time_s + 0.01;
  const auto start = std::chrono::steady_clock::now();
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::uint64_t n = first_index + i;
    RecordedSample sample = samples[n % samples.size()];
    sample.input.time_s += period_s * static_cast<double>(n / samples.size());
    const auto due = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                 std::chrono::duration<double>(static_cast<double>(i) / rate_hz));
    if (due > std::chrono::steady_clock::now()) {
      publisher.flush();
      std::this_thread::sleep_until(due);
    }
    publisher.add(sample);
  }
  publisher.flush();
  return count;
}

}  // namespace gc::test
