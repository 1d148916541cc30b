#include "diagnosis/synthesis/load_sequence.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/model_error.h"

namespace gc {
namespace {

// Position u in [0, 1) along a triangle 0 -> 1 -> -1 -> 0: the applied-moment cycle.
double triangle_cycle(double u) {
  if (u < 0.25) return 4.0 * u;
  if (u < 0.75) return 2.0 - 4.0 * u;
  return 4.0 * u - 4.0;
}

// Position u in [0, 1) along 0 -> 1 -> 0: up then down again.
double up_and_down(double u) { return u < 0.5 ? 2.0 * u : 2.0 - 2.0 * u; }

// Which of `parts` equal segments u lies in, and where inside it (0..1).
std::pair<std::size_t, double> segment(double u, std::size_t parts) {
  const double scaled = u * static_cast<double>(parts);
  const auto index = std::min(parts - 1, static_cast<std::size_t>(scaled));
  return {index, scaled - static_cast<double>(index)};
}

void fill_moment_sweep(double u, const LoadSequenceOptions& o, MeasurementSample& s) {
  const auto [block, v] = segment(u, o.sweep_torque_fractions.size());
  s.torque_nm = o.sweep_torque_fractions[block] * o.reference_torque_nm;
  set_signed_misalignment(o.sweep_peak_fraction * triangle_cycle(v), o, s);
}

void fill_torque_sweep(double u, const LoadSequenceOptions& o, MeasurementSample& s) {
  const auto [block, v] = segment(u, o.sweep_misalignment_fractions.size());
  const double fraction =
      o.sweep_low_fraction + (o.sweep_high_fraction - o.sweep_low_fraction) * up_and_down(v);
  s.torque_nm = fraction * o.reference_torque_nm;
  set_signed_misalignment(o.sweep_misalignment_fractions[block], o, s);
}

void fill_torque_ramp(double u, const LoadSequenceOptions& o, MeasurementSample& s) {
  const auto [step, v] = segment(u, static_cast<std::size_t>(o.ramp_steps));
  (void)v;
  const double share = static_cast<double>(step) / static_cast<double>(o.ramp_steps - 1);
  s.torque_nm = o.ramp_first_torque_nm + (o.ramp_last_torque_nm - o.ramp_first_torque_nm) * share;
  set_signed_misalignment(o.ramp_misalignment_fraction, o, s);
}

void require_not_empty(const std::string& field, std::size_t size) {
  if (size == 0) throw InvalidInput(field, "must list at least one value");
}

void validate(const LoadSequenceOptions& o) {
  if (o.samples < 2) throw InvalidInput("sequence.samples", o.samples, ">= 2");
  require_positive("sequence.jam_angle_rad", o.jam_angle_rad);
  require_positive("sequence.reference_torque_nm", o.reference_torque_nm);
  require_positive("sequence.sample_period_s", o.sample_period_s);
  require_finite("sequence.direction_rad", o.direction_rad);
  require_not_empty("sequence.sweep_torque_fractions", o.sweep_torque_fractions.size());
  require_not_empty("sequence.sweep_misalignment_fractions",
                    o.sweep_misalignment_fractions.size());
  if (o.ramp_steps < 2) throw InvalidInput("sequence.ramp_steps", o.ramp_steps, ">= 2");
}

}  // namespace

std::optional<LoadSequenceKind> load_sequence_kind(std::string_view name) {
  for (auto kind : {LoadSequenceKind::moment_sweep, LoadSequenceKind::torque_sweep,
                    LoadSequenceKind::torque_ramp}) {
    if (to_string(kind) == name) return kind;
  }
  return std::nullopt;
}

std::string_view to_string(LoadSequenceKind kind) {
  switch (kind) {
    case LoadSequenceKind::moment_sweep: return "moment-sweep";
    case LoadSequenceKind::torque_sweep: return "torque-sweep";
    case LoadSequenceKind::torque_ramp: return "torque-ramp";
  }
  return "";
}

void set_signed_misalignment(double fraction, const LoadSequenceOptions& options,
                             MeasurementSample& sample) {
  sample.misalignment_rad = std::abs(fraction) * options.jam_angle_rad;
  double direction = options.direction_rad + (fraction < 0.0 ? std::numbers::pi : 0.0);
  // Keep beta in (-pi, pi], as a recording would.
  if (direction > std::numbers::pi) direction -= 2.0 * std::numbers::pi;
  sample.direction_rad = direction;
}

std::vector<MeasurementSample> load_sequence(const LoadSequenceOptions& options) {
  validate(options);
  std::vector<MeasurementSample> samples(static_cast<std::size_t>(options.samples));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double u = static_cast<double>(i) / static_cast<double>(samples.size());
    MeasurementSample& s = samples[i];
    s.time_s = static_cast<double>(i) * options.sample_period_s;
    switch (options.kind) {
      case LoadSequenceKind::moment_sweep: fill_moment_sweep(u, options, s); break;
      case LoadSequenceKind::torque_sweep: fill_torque_sweep(u, options, s); break;
      case LoadSequenceKind::torque_ramp: fill_torque_ramp(u, options, s); break;
    }
  }
  return samples;
}

}  // namespace gc
