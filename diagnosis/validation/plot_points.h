// A bounded, evenly spaced subset of a recording with the model's predictions, for plots.
// Keeps every stride-th sample and doubles the stride whenever the subset is full, so memory
// stays bounded whatever the recording's length. The kept positions depend only on the sample
// count, so samplers fed the same recording keep the same samples: two models' points line up.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/recorded_sample.h"

namespace gc {

struct ComparedPoint {
  RecordedSample recorded;
  std::optional<SensorMoments> predicted;  ///< absent when the model refused the sample
};

class PointSampler {
 public:
  explicit PointSampler(std::size_t capacity = 4000) : capacity_(capacity < 2 ? 2 : capacity) {}

  void add(const RecordedSample& sample, const std::optional<SensorMoments>& predicted);
  const std::vector<ComparedPoint>& points() const { return points_; }
  std::size_t stride() const { return stride_; }

 private:
  std::size_t capacity_;
  std::size_t stride_ = 1;
  std::size_t seen_ = 0;
  std::vector<ComparedPoint> points_;
};

}  // namespace gc
