// The inputs of a sequence up to one of its samples, for a model output that depends on the
// history (a rig's mode ringing after a change of the load, core/effects/ringing_response.h) and
// not on the sample alone. A view: a recording or a sequence of inputs, in time order, and the
// index of the sample predicted (CouplingModel::predict_at).
#pragma once

#include <cstddef>
#include <span>

#include "core/measurement_sample.h"
#include "core/recorded_sample.h"

namespace gc {

class InputHistory {
 public:
  InputHistory(std::span<const RecordedSample> recording, std::size_t i) : recording_(recording), index_(i) {}
  InputHistory(std::span<const MeasurementSample> sequence, std::size_t i) : sequence_(sequence), index_(i) {}

  /// The sample predicted.
  std::size_t index() const { return index_; }
  /// The inputs of sample k <= index().
  const MeasurementSample& at(std::size_t k) const { return recording_.empty() ? sequence_[k] : recording_[k].input; }

 private:
  std::span<const RecordedSample> recording_;
  std::span<const MeasurementSample> sequence_;
  std::size_t index_;
};

}  // namespace gc
