#include "core/input_timing.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <type_traits>

namespace gc {
namespace {

double lerp(double a, double b, double w) { return a + w * (b - a); }

std::optional<double> lerp(const std::optional<double>& a, const std::optional<double>& b, double w) {
  if (a && b) return lerp(*a, *b, w);
  return w < 0.5 ? a : b;
}

/// An angle between a and b along the shorter arc.
double lerp_angle(double a, double b, double w) {
  return a + w * std::remainder(b - a, 2.0 * std::numbers::pi);
}

/// Index access to either kind of sequence.
template <typename Sequence>
const MeasurementSample& input_of(const Sequence& s, std::size_t k) {
  if constexpr (std::is_same_v<typename Sequence::value_type, RecordedSample>) {
    return s[k].input;
  } else {
    return s[k];
  }
}

/// The inputs at time `t`: the neighbours found by walking from `from`, which is near it (a
/// delay is a few samples), so neither sorting nor a search of the whole sequence is needed.
template <typename Sequence>
MeasurementSample input_at(const Sequence& s, std::size_t from, double t) {
  const std::size_t n = s.size();
  std::size_t j = from;
  while (j > 0 && input_of(s, j).time_s > t) --j;
  while (j + 1 < n && input_of(s, j + 1).time_s <= t) ++j;
  const MeasurementSample& a = input_of(s, j);
  if (j + 1 >= n || t <= a.time_s) return a;
  const MeasurementSample& b = input_of(s, j + 1);
  const double span = b.time_s - a.time_s;
  const double w = span > 0.0 ? (t - a.time_s) / span : 0.0;
  MeasurementSample out = a;
  out.torque_nm = lerp(a.torque_nm, b.torque_nm, w);
  out.misalignment_rad = lerp(a.misalignment_rad, b.misalignment_rad, w);
  out.direction_rad = lerp_angle(a.direction_rad, b.direction_rad, w);
  out.speed_rpm = lerp(a.speed_rpm, b.speed_rpm, w);
  out.temperature_c = lerp(a.temperature_c, b.temperature_c, w);
  out.rotation_phase_rad = lerp(a.rotation_phase_rad, b.rotation_phase_rad, w);
  out.misalignment_rate_rad_s = lerp(a.misalignment_rate_rad_s, b.misalignment_rate_rad_s, w);
  out.torque_rate_nm_s = lerp(a.torque_rate_nm_s, b.torque_rate_nm_s, w);
  out.applied_moment_y_nm = lerp(a.applied_moment_y_nm, b.applied_moment_y_nm, w);
  out.applied_moment_z_nm = lerp(a.applied_moment_z_nm, b.applied_moment_z_nm, w);
  return out;
}

/// Running sums of the inputs over a window, for their mean.
struct InputMean {
  double count = 0.0, torque = 0.0, zeta = 0.0, cos_beta = 0.0, sin_beta = 0.0;
  void add(const MeasurementSample& s) {
    count += 1.0;
    torque += s.torque_nm;
    zeta += s.misalignment_rad;
    cos_beta += std::cos(s.direction_rad);
    sin_beta += std::sin(s.direction_rad);
  }
  /// `at` with the window's mean torque, misalignment and direction.
  MeasurementSample applied_to(MeasurementSample at) const {
    at.torque_nm = torque / count;
    at.misalignment_rad = zeta / count;
    if (cos_beta != 0.0 || sin_beta != 0.0) at.direction_rad = std::atan2(sin_beta, cos_beta);
    return at;
  }
};

template <typename Sequence>
MeasurementSample timed(const Sequence& s, std::size_t i, const InputTiming& timing) {
  const double t_i = input_of(s, i).time_s;
  const double end = t_i - timing.delay_s;
  MeasurementSample out = input_at(s, i, end);
  if (timing.average_s > 0.0) {
    InputMean mean;
    mean.add(out);
    // The samples inside (end - average_s, end], walking back from the last at or before `end`:
    // found from i in either direction, since a negative delay puts `end` after t_i.
    std::size_t k = i;
    while (k > 0 && input_of(s, k).time_s > end) --k;
    while (k + 1 < s.size() && input_of(s, k + 1).time_s <= end) ++k;
    for (; input_of(s, k).time_s > end - timing.average_s; --k) {
      if (input_of(s, k).time_s <= end) mean.add(input_of(s, k));
      if (k == 0) break;
    }
    out = mean.applied_to(out);
  }
  out.time_s = t_i;
  out.inputs_timed = true;
  return out;
}

}  // namespace

MeasurementSample timed_input(std::span<const MeasurementSample> sequence, std::size_t i, const InputTiming& timing) {
  return timed(sequence, i, timing);
}

MeasurementSample timed_input(std::span<const RecordedSample> recording, std::size_t i, const InputTiming& timing) {
  return timed(recording, i, timing);
}

}  // namespace gc
