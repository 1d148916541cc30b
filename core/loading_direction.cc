#include "core/loading_direction.h"

#include <algorithm>
#include <vector>

#include "core/input_noise.h"

namespace gc {

double loading_dead_band_rad(std::span<const double> misalignment_rad,
                             const LoadingDirectionOptions& options) {
  return std::max(options.min_dead_band_rad,
                  options.noise_multiple * input_noise_sigma(misalignment_rad));
}

int LoadingDirectionTracker::next(double time_s, double misalignment_rad) {
  if (!started_) {
    started_ = true;
    anchor_rad_ = misalignment_rad;
    anchor_time_s_ = time_s;
    return direction_;
  }
  const double change = misalignment_rad - anchor_rad_;
  if (change > dead_band_rad_ || change < -dead_band_rad_) {
    direction_ = change > 0.0 ? 1 : -1;
    anchor_rad_ = misalignment_rad;
    anchor_time_s_ = time_s;
  } else if (time_s - anchor_time_s_ > still_after_s_) {
    direction_ = 0;
  }
  if (direction_ != 0) last_travel_ = direction_;
  return direction_;
}

void derive_loading_directions(std::span<MeasurementSample> samples,
                               const LoadingDirectionOptions& options) {
  std::vector<double> amplitudes(samples.size());
  std::transform(samples.begin(), samples.end(), amplitudes.begin(),
                 [](const MeasurementSample& s) { return s.misalignment_rad; });
  LoadingDirectionTracker tracker(loading_dead_band_rad(amplitudes, options), options.still_after_s);
  for (MeasurementSample& s : samples) {
    s.loading_direction = tracker.next(s.time_s, s.misalignment_rad);
    s.travel_direction = tracker.last_travel();
  }
}

}  // namespace gc
