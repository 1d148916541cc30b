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

/// Sample k's time, from `columns` where they hold it (the same number, nearer in memory).
template <typename Sequence>
double time_at(const Sequence& s, std::size_t k, const WindowColumns* columns) {
  return columns && columns->holds(k) ? columns->time_s[k - columns->first] : input_of(s, k).time_s;
}

/// The inputs at time `t`: the neighbours found by walking from `from`, which is near it (a
/// delay is a few samples), so neither sorting nor a search of the whole sequence is needed.
template <typename Sequence>
MeasurementSample input_at(const Sequence& s, std::size_t from, double t, const WindowColumns* columns) {
  const std::size_t n = s.size();
  const auto time_of = [&](std::size_t k) { return time_at(s, k, columns); };
  std::size_t j = from;
  while (j > 0 && time_of(j) > t) --j;
  while (j + 1 < n && time_of(j + 1) <= t) ++j;
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
    add(s.torque_nm, s.misalignment_rad, std::cos(s.direction_rad), std::sin(s.direction_rad));
  }
  void add(const WindowColumns& c, std::size_t k) {
    const std::size_t j = k - c.first;
    add(c.torque_nm[j], c.misalignment_rad[j], c.cos_beta[j], c.sin_beta[j]);
  }
  void add(double torque_nm, double misalignment_rad, double cos_direction, double sin_direction) {
    count += 1.0;
    torque += torque_nm;
    zeta += misalignment_rad;
    cos_beta += cos_direction;
    sin_beta += sin_direction;
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
MeasurementSample timed(const Sequence& s, std::size_t i, const InputTiming& timing,
                        const WindowColumns* columns = nullptr) {
  const double t_i = input_of(s, i).time_s;
  const double end = t_i - timing.delay_s;
  MeasurementSample out = input_at(s, i, end, columns);
  if (timing.average_s > 0.0) {
    InputMean mean;
    mean.add(out);
    // The samples inside (end - average_s, end], walking back from the last at or before `end`:
    // found from i in either direction, since a negative delay puts `end` after t_i.
    const auto time_of = [&](std::size_t k) { return time_at(s, k, columns); };
    std::size_t k = i;
    while (k > 0 && time_of(k) > end) --k;
    while (k + 1 < s.size() && time_of(k + 1) <= end) ++k;
    for (; time_of(k) > end - timing.average_s; --k) {
      if (time_of(k) <= end) {
        if (columns && columns->holds(k)) {
          mean.add(*columns, k);
        } else {
          mean.add(input_of(s, k));
        }
      }
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

MeasurementSample timed_input(std::span<const RecordedSample> recording, std::size_t i, const InputTiming& timing,
                              const WindowColumns* columns) {
  return timed(recording, i, timing, columns);
}

WindowColumns::WindowColumns(std::span<const RecordedSample> recording, std::size_t first_sample, std::size_t last_sample)
    : first(first_sample) {
  for (std::size_t k = first_sample; k <= last_sample && k < recording.size(); ++k) {
    const MeasurementSample& s = recording[k].input;
    time_s.push_back(s.time_s);
    torque_nm.push_back(s.torque_nm);
    misalignment_rad.push_back(s.misalignment_rad);
    cos_beta.push_back(std::cos(s.direction_rad));
    sin_beta.push_back(std::sin(s.direction_rad));
  }
}

}  // namespace gc
