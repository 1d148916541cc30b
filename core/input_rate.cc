#include "core/input_rate.h"

namespace gc {

std::optional<double> InputRateTracker::next(double time_s, double value) {
  window_.emplace_back(time_s, value);
  // A sample exactly window_s old stays, whatever the rounding of the times: 0.5 s at 10 Hz is
  // 6 samples.
  const double oldest = time_s - options_.window_s * (1.0 + 1e-9);
  while (window_.front().first < oldest) window_.pop_front();
  if (static_cast<int>(window_.size()) < options_.min_samples) return std::nullopt;
  // The slope about the window's means, so that large times lose no digits.
  double mean_t = 0.0, mean_v = 0.0;
  for (const auto& [t, v] : window_) { mean_t += t; mean_v += v; }
  mean_t /= static_cast<double>(window_.size());
  mean_v /= static_cast<double>(window_.size());
  double stt = 0.0, stv = 0.0;
  for (const auto& [t, v] : window_) {
    stt += (t - mean_t) * (t - mean_t);
    stv += (t - mean_t) * (v - mean_v);
  }
  if (!(stt > 0.0)) return std::nullopt;
  return stv / stt;
}

void derive_input_rates(std::span<MeasurementSample> samples, const InputRateOptions& options) {
  InputRateTracker misalignment(options), torque(options);
  for (MeasurementSample& s : samples) {
    s.misalignment_rate_rad_s = misalignment.next(s.time_s, s.misalignment_rad);
    s.torque_rate_nm_s = torque.next(s.time_s, s.torque_nm);
  }
}

}  // namespace gc
