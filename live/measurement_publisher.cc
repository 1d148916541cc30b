#include "live/measurement_publisher.h"

#include <algorithm>

#include "live/live_names.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "protocol/random_id.h"

namespace gc::live {

using protocol::check_dds;

MeasurementPublisher::MeasurementPublisher(dds_entity_t participant, const std::string& test_cell)
    : test_cell_(test_cell), run_id_(protocol::random_id()) {
  require_test_cell_name(test_cell);
  publisher_ = make_cell_publisher(participant, test_cell);
  topic_ = make_measurement_topic(participant);
  const protocol::Qos qos = measurement_writer_qos();
  writer_ = protocol::Entity(check_dds(
      dds_create_writer(publisher_.get(), topic_.get(), qos.get(), nullptr),
      "dds_create_writer(measurement)"));
  queued_.reserve(kMaxBatchSamples);
  optionals_.resize(kMaxBatchSamples);  // never reallocated: queued samples point into it
}

MeasurementPublisher::~MeasurementPublisher() {
  // The run is over: readers see the test cell's instance unregistered (not disposed: the
  // test cell may come back with a new run).
  try {
    flush();
  } catch (...) {
  }
}

void MeasurementPublisher::add(const RecordedSample& sample) {
  if (queued_.size() == kMaxBatchSamples) flush();
  queued_.push_back(to_wire(sample, next_sequence_++, optionals_[queued_.size()]));
}

void MeasurementPublisher::flush() {
  if (queued_.empty()) return;
  gearcoupling_MeasurementBatch batch{};
  std::copy_n(test_cell_.c_str(), test_cell_.size() + 1, batch.test_cell);
  batch.run_id = run_id_;
  batch.samples._buffer = queued_.data();
  batch.samples._length = batch.samples._maximum = static_cast<std::uint32_t>(queued_.size());
  batch.samples._release = false;
  // A busy reader (a monitor starved of CPU for a second) is not a lost one: wait for it, as
  // KEEP_ALL promises, but not forever. A dead reader is unmatched by liveliness, so a write
  // that still times out after `patience_` has a reader alive and stuck.
  const auto start = std::chrono::steady_clock::now();
  dds_return_t rc = dds_write(writer_.get(), &batch);
  while (rc == DDS_RETCODE_TIMEOUT && std::chrono::steady_clock::now() - start < patience_) {
    ++retried_writes_;
    rc = dds_write(writer_.get(), &batch);
  }
  if (rc == DDS_RETCODE_TIMEOUT) {
    const double waited_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    throw protocol::DdsError("dds_write(measurement) of " + std::to_string(queued_.size()) +
                                 " samples of test cell " + test_cell_ + ", still blocked by a "
                                 "reader after " + std::to_string(waited_s) + " s (kept queued),",
                             rc);
  }
  check_dds(rc, "dds_write(measurement)");
  queued_.clear();
}

bool MeasurementPublisher::wait_for_readers(std::uint32_t readers,
                                            std::chrono::milliseconds timeout) const {
  return live::wait_for_readers(writer_.get(), readers, timeout);
}

}  // namespace gc::live
