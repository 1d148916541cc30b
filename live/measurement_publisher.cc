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
  queued_.clear();
  check_dds(dds_write(writer_.get(), &batch), "dds_write(measurement)");
}

bool MeasurementPublisher::wait_for_readers(std::uint32_t readers,
                                            std::chrono::milliseconds timeout) const {
  return live::wait_for_readers(writer_.get(), readers, timeout);
}

}  // namespace gc::live
