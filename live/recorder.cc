#include "live/recorder.h"

#include <chrono>

#include "analysis/recording_csv.h"
#include "core/model_error.h"
#include "gearcoupling.h"
#include "live/live_names.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "live/measurement_wire.h"
#include "protocol/samples.h"

namespace gc::live {

using protocol::check_dds;
using Clock = std::chrono::steady_clock;

Capture capture_measurements(dds_entity_t participant, const RecordOptions& options) {
  require_test_cell_name(options.test_cell);
  require_in_range("record.seconds", options.seconds, 1e-3, 1e7);
  protocol::Entity subscriber =
      make_subscriber_in(participant, {kLivePartition, cell_partition(options.test_cell)});
  protocol::Entity topic = make_measurement_topic(participant);
  const protocol::Qos qos = measurement_reader_qos();
  protocol::Entity reader(check_dds(dds_create_reader(subscriber.get(), topic.get(), qos.get(), nullptr),
                                    "dds_create_reader(measurement)"));
  protocol::Entity waitset(check_dds(dds_create_waitset(participant), "dds_create_waitset"));
  check_dds(dds_set_status_mask(reader.get(), DDS_DATA_AVAILABLE_STATUS), "dds_set_status_mask");
  check_dds(dds_waitset_attach(waitset.get(), reader.get(), reader.get()), "dds_waitset_attach");

  Capture capture;
  std::uint64_t run_id = 0;
  const Clock::time_point end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.seconds));
  for (Clock::time_point now = Clock::now(); now < end; now = Clock::now()) {
    dds_waitset_wait(waitset.get(), nullptr, 0,
                     std::chrono::duration_cast<std::chrono::nanoseconds>(end - now).count());
    for (;;) {
      protocol::LoanedSamples<gearcoupling_MeasurementBatch, 64> batches(reader.get());
      if (batches.size() == 0) break;
      for (std::size_t i = 0; i < batches.size(); ++i) {
        if (!batches.info(i).valid_data || options.test_cell != batches[i].test_cell) continue;
        if (batches[i].run_id != run_id) ++capture.runs;
        run_id = batches[i].run_id;
        const auto& samples = batches[i].samples;
        for (std::uint32_t k = 0; k < samples._length; ++k) {
          try {
            capture.samples.push_back(from_wire(samples._buffer[k]));
          } catch (const InvalidInput& error) {
            if (capture.refused++ == 0) capture.first_refusal = error.what();
          }
        }
      }
    }
  }
  return capture;
}

std::string capture_csv(const Capture& capture) {
  if (capture.samples.empty()) return analysis::recording_header(RecordedSample{});
  std::string text = analysis::recording_header(capture.samples.front());
  for (const RecordedSample& sample : capture.samples) analysis::append_recording_row(text, sample);
  return text;
}

}  // namespace gc::live
