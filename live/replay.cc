#include "live/replay.h"

#include <chrono>
#include <thread>
#include <vector>

#include "core/model_error.h"
#include "live/measurement_publisher.h"

namespace gc::live {
namespace {

using Clock = std::chrono::steady_clock;

void require_pace(const ReplayOptions& options) {
  if (options.rate_hz.has_value() == options.speed.has_value()) {
    throw InvalidInput("replay.rate", "give exactly one of --rate HZ and --speed X");
  }
  if (options.rate_hz) require_in_range("replay.rate", *options.rate_hz, 1e-3, 1e6);
  if (options.speed) require_in_range("replay.speed", *options.speed, 1e-3, 1e6);
}

}  // namespace

ReplayResult replay_recording(dds_entity_t participant, const std::filesystem::path& path,
                              const ReplayOptions& options) {
  require_pace(options);
  analysis::RecordingReader reader(path, options.recording);
  MeasurementPublisher publisher(participant, options.test_cell);
  if (options.wait_for_readers > 0 &&
      !publisher.wait_for_readers(options.wait_for_readers,
                                  std::chrono::milliseconds(static_cast<long>(options.wait_s * 1e3)))) {
    throw InvalidInput("replay", "no reader of the measurement topic matched within " +
                                     format_number(options.wait_s) + " s (is the monitor running?)");
  }
  ReplayResult result{publisher.run_id()};
  std::vector<RecordedSample> chunk;
  std::optional<double> first_time_s;
  const Clock::time_point start = Clock::now();
  std::size_t queued = 0;
  // When sample `index` (recording time `time_s`) is due.
  const auto due = [&](std::uint64_t index, double time_s) {
    const double offset_s = options.rate_hz ? static_cast<double>(index) / *options.rate_hz
                                            : (time_s - *first_time_s) / *options.speed;
    return start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(offset_s));
  };
  while (reader.next_chunk(chunk, 4096)) {
    for (const RecordedSample& sample : chunk) {
      if (!first_time_s) first_time_s = sample.input.time_s;
      const Clock::time_point when = due(result.published, sample.input.time_s);
      // A sample not yet due: send what is queued first, so no sample waits for a later one.
      if (when > Clock::now()) {
        publisher.flush();
        queued = 0;
        std::this_thread::sleep_until(when);
      }
      publisher.add(sample);
      ++result.published;
      if (++queued >= options.max_batch) {
        publisher.flush();
        queued = 0;
      }
    }
  }
  publisher.flush();
  result.excluded_rows = reader.excluded_rows();
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace gc::live
