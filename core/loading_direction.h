// Whether the misalignment amplitude rises or falls, derived from the sequence of samples so
// that effects (e.g. hysteresis) need no per-call state (MeasurementSample::loading_direction).
#pragma once

namespace gc {

struct LoadingDirectionOptions {
  /// Changes of the amplitude smaller than this are noise, not a direction [rad].
  double dead_band_rad = 2e-5;
  /// The amplitude counts as still once it has stayed within the dead band this long [s].
  double still_after_s = 0.5;
};

/// Follows one recording sample by sample. The amplitude is compared with an anchor, the
/// amplitude where the direction was last confirmed: beyond +dead band it rises (+1), beyond
/// -dead band it falls (-1), and within the band the last direction holds until still_after_s
/// has passed (0). A value type: one per recording, fed in time order.
class LoadingDirectionTracker {
 public:
  explicit LoadingDirectionTracker(LoadingDirectionOptions options = {}) : options_(options) {}

  /// The direction at this sample: +1 rising, -1 falling, 0 still or unknown (the first).
  int next(double time_s, double misalignment_rad);

 private:
  LoadingDirectionOptions options_;
  bool started_ = false;
  double anchor_rad_ = 0.0;
  double anchor_time_s_ = 0.0;
  int direction_ = 0;
};

}  // namespace gc
