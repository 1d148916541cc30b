// Publishes one test cell's samples as a live test cell does (MeasurementBatch, one run):
// numbers them from 1, batches them, and writes a batch on flush(). Used by `gearcoupling
// replay` and the benchmarks; a third-party DAQ does the same from docs/protocol.md.
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "core/recorded_sample.h"
#include "gearcoupling.h"
#include "live/measurement_wire.h"
#include "protocol/dds_entity.h"

namespace gc::live {

class MeasurementPublisher {
 public:
  /// Throws InvalidInput naming "test_cell" for a bad name.
  MeasurementPublisher(dds_entity_t participant, const std::string& test_cell);
  ~MeasurementPublisher();

  /// Queues `sample` for the next batch (flushes first when the batch is full).
  void add(const RecordedSample& sample);
  /// Writes the queued samples as one MeasurementBatch (nothing when none is queued). A reader
  /// that must lose nothing and falls behind makes each dds_write wait up to 1 s (live_qos.h);
  /// the write is tried again until `patience` has passed, then a protocol error says how long
  /// the batch waited and the samples stay queued for the next flush.
  void flush();
  /// How long flush() waits in all for a reader that has fallen behind (30 s unless set).
  void set_patience(std::chrono::milliseconds patience) { patience_ = patience; }
  /// How many dds_write calls timed out and were tried again.
  std::uint64_t retried_writes() const { return retried_writes_; }
  /// Waits until at least `readers` readers are matched (a sample written before is lost to
  /// them). Returns whether they were.
  bool wait_for_readers(std::uint32_t readers, std::chrono::milliseconds timeout) const;

  std::uint64_t run_id() const { return run_id_; }
  std::uint64_t samples_written() const { return next_sequence_ - 1 - queued_.size(); }

 private:
  std::string test_cell_;
  std::uint64_t run_id_;
  std::uint64_t next_sequence_ = 1;
  std::chrono::milliseconds patience_{30000};
  std::uint64_t retried_writes_ = 0;
  protocol::Entity publisher_, topic_, writer_;
  std::vector<gearcoupling_Measurement> queued_;
  std::vector<MeasurementOptionals> optionals_;
};

}  // namespace gc::live
