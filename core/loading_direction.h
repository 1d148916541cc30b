// Whether the misalignment amplitude rises or falls, derived from the sequence of samples so
// that effects (e.g. hysteresis) need no per-call state (MeasurementSample::loading_direction).
#pragma once

#include <span>

#include "core/measurement_sample.h"

namespace gc {

struct LoadingDirectionOptions {
  /// Smallest dead band [rad]: changes below it are never a direction, however clean the
  /// recording. It only decides on recordings without measurable misalignment noise, and there
  /// a wide band delays every turn: a slow sweep (3e-6 rad a sample) needs about 7 samples to
  /// cross 2e-5 rad, the floor before issue 22, so a travel-direction hysteresis read the wrong
  /// sign on 1.6 % of a 10 Hz campaign's samples. 1e-6 rad is 0.06 millidegree, a thirtieth of
  /// the bundled sweeps' smallest step (so their labels stand); any noise above 1.7e-7 rad
  /// widens the band beyond it (6 sigma).
  double min_dead_band_rad = 1e-6;
  /// The dead band is this many noise sigmas of the recording's misalignment
  /// (core/input_noise.h) when that is wider than min_dead_band_rad [-]. Two samples of a hold
  /// differ by sqrt(2) sigma rms, so 6 sigma is 4.2 of their sigmas: about one false direction
  /// in 45,000 still samples (docs/recordings.md has the trade-off measured).
  double noise_multiple = 6.0;
  /// The amplitude counts as still once it has stayed within the dead band this long [s].
  double still_after_s = 0.5;
};

/// The dead band for a recording whose misalignment amplitudes, in time order, are
/// `misalignment_rad`: max(min_dead_band_rad, noise_multiple * input_noise_sigma) [rad].
double loading_dead_band_rad(std::span<const double> misalignment_rad,
                             const LoadingDirectionOptions& options = {});

/// Follows one recording sample by sample. The amplitude is compared with an anchor, the
/// amplitude where the direction was last confirmed: beyond +dead band it rises (+1), beyond
/// -dead band it falls (-1), and within the band the last direction holds until still_after_s
/// has passed (0). A value type: one per recording, fed in time order.
class LoadingDirectionTracker {
 public:
  /// dead_band_rad [rad], e.g. from loading_dead_band_rad(); still_after_s [s].
  LoadingDirectionTracker(double dead_band_rad, double still_after_s)
      : dead_band_rad_(dead_band_rad), still_after_s_(still_after_s) {}

  /// The direction at this sample: +1 rising, -1 falling, 0 still or unknown (the first).
  int next(double time_s, double misalignment_rad);
  /// The last non-zero direction returned by next (held through still stretches), 0 before any.
  int last_travel() const { return last_travel_; }

 private:
  double dead_band_rad_;
  double still_after_s_;
  bool started_ = false;
  double anchor_rad_ = 0.0;
  double anchor_time_s_ = 0.0;
  int direction_ = 0;
  int last_travel_ = 0;
};

/// Sets loading_direction on every sample of a whole recording, in time order: the dead band
/// from the recording's own misalignment noise (loading_dead_band_rad), then the tracker.
void derive_loading_directions(std::span<MeasurementSample> samples,
                               const LoadingDirectionOptions& options = {});

}  // namespace gc
