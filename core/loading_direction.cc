#include "core/loading_direction.h"

namespace gc {

int LoadingDirectionTracker::next(double time_s, double misalignment_rad) {
  if (!started_) {
    started_ = true;
    anchor_rad_ = misalignment_rad;
    anchor_time_s_ = time_s;
    return direction_;
  }
  const double change = misalignment_rad - anchor_rad_;
  if (change > options_.dead_band_rad || change < -options_.dead_band_rad) {
    direction_ = change > 0.0 ? 1 : -1;
    anchor_rad_ = misalignment_rad;
    anchor_time_s_ = time_s;
  } else if (time_s - anchor_time_s_ > options_.still_after_s) {
    direction_ = 0;
  }
  return direction_;
}

}  // namespace gc
