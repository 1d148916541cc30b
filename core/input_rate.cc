#include "core/input_rate.h"

#include <algorithm>

namespace gc {

void InputRateTracker::rebuild_sums() {
  anchor_t_ = window_.front().first;
  anchor_v_ = window_.front().second;
  sum_t_ = sum_v_ = sum_tt_ = sum_tv_ = 0.0;
  for (const auto& [t, v] : window_) {
    const double dt = t - anchor_t_, dv = v - anchor_v_;
    sum_t_ += dt;
    sum_v_ += dv;
    sum_tt_ += dt * dt;
    sum_tv_ += dt * dv;
  }
}

std::optional<double> InputRateTracker::next(double time_s, double value) {
  if (window_.empty()) {
    anchor_t_ = time_s;
    anchor_v_ = value;
  }
  window_.emplace_back(time_s, value);
  const double dt = time_s - anchor_t_, dv = value - anchor_v_;
  sum_t_ += dt;
  sum_v_ += dv;
  sum_tt_ += dt * dt;
  sum_tv_ += dt * dv;
  // A sample exactly window_s old stays, whatever the rounding of the times: 0.5 s at 10 Hz is
  // 6 samples.
  const double oldest = time_s - options_.window_s * (1.0 + 1e-9);
  while (window_.front().first < oldest) {
    const double old_dt = window_.front().first - anchor_t_, old_dv = window_.front().second - anchor_v_;
    sum_t_ -= old_dt;
    sum_v_ -= old_dv;
    sum_tt_ -= old_dt * old_dt;
    sum_tv_ -= old_dt * old_dv;
    window_.pop_front();
  }
  // The anchor more than a window behind the oldest sample: sums about a nearer one, once per
  // window (O(1) per sample on average), so their rounding never builds up.
  if (window_.front().first - anchor_t_ > options_.window_s) rebuild_sums();
  if (static_cast<int>(window_.size()) < options_.min_samples) return std::nullopt;
  // The slope about the window's means: S_tt - S_t^2 / n and S_tv - S_t S_v / n.
  const double n = static_cast<double>(window_.size());
  const double stt = sum_tt_ - sum_t_ * sum_t_ / n;
  const double stv = sum_tv_ - sum_t_ * sum_v_ / n;
  // Below rounding of the sums: the window has no spread in time.
  if (!(stt > 1e-12 * std::max(sum_tt_, 1e-300))) return std::nullopt;
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
