#include "diagnosis/validation/plot_points.h"

namespace gc {

void PointSampler::add(const RecordedSample& sample,
                       const std::optional<SensorMoments>& predicted) {
  const std::size_t index = seen_++;
  if (index % stride_ != 0) return;
  points_.push_back({sample, predicted});
  if (points_.size() <= capacity_) return;
  // Keep the points at even multiples of the stride: positions 0, 2, 4, ... of the subset.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points_.size(); i += 2) points_[kept++] = points_[i];
  points_.resize(kept);
  stride_ *= 2;
}

}  // namespace gc
