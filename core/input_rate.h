// Rates of the inputs as derived inputs (MeasurementSample::misalignment_rate_rad_s,
// torque_rate_nm_s): how fast the misalignment and the torque change, for mechanisms that go
// with speed of travel rather than its sign (viscous damping of the spline's oil film, a
// channel sampled late: M(t - tau) ~ M - tau dM/dt). Like the loading direction and the rotation
// phase, they come from the sequence, so effects and formula terms need no per-call state.
//
// The rate at a sample is the least-squares slope of the input over the samples of the last
// `window_s` seconds up to and including it: backward-looking, so a reader that streams a
// recording (or a live test cell) can give it at once; it lags the true rate by about half the
// window. Its noise is sigma / sqrt(sum (t - mean t)^2): over 0.5 s at 10 Hz (6 samples),
// 2.4 sigma per s, against 14 sigma per s for the difference of two successive samples.
#pragma once

#include <deque>
#include <optional>
#include <span>

#include "core/measurement_sample.h"

namespace gc {

struct InputRateOptions {
  double window_s = 0.5;   ///< the slope's window [s]
  int min_samples = 3;     ///< fewer samples in the window give no rate
};

/// Follows one input of one recording sample by sample (a value type, fed in time order).
class InputRateTracker {
 public:
  explicit InputRateTracker(InputRateOptions options = {}) : options_(options) {}
  /// The rate at this sample [unit of value per s], nullopt while the window holds fewer than
  /// min_samples samples or no spread in time.
  std::optional<double> next(double time_s, double value);

 private:
  /// The sums about the anchor afresh from the window (when the anchor has grown old).
  void rebuild_sums();

  InputRateOptions options_;
  std::deque<std::pair<double, double>> window_;  ///< (time [s], value)
  // Running sums of dt = t - anchor_t and dv = v - anchor_v over the window, so each sample
  // costs O(1) however many the window holds (5000 at 10 kHz). Taken about an anchor in the
  // window, renewed every window, so that large times and values lose no digits.
  double anchor_t_ = 0.0, anchor_v_ = 0.0;
  double sum_t_ = 0.0, sum_v_ = 0.0, sum_tt_ = 0.0, sum_tv_ = 0.0;
};

/// Sets misalignment_rate_rad_s and torque_rate_nm_s on every sample of a recording in time order.
void derive_input_rates(std::span<MeasurementSample> samples, const InputRateOptions& options = {});

}  // namespace gc
