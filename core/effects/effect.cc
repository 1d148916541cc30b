#include "core/effects/effect.h"

#include <algorithm>
#include <cmath>

#include "core/model_error.h"

namespace gc {

Effect::Effect(const EffectInfo& info, const ParameterValues& values) : info_(info) {
  for (const auto& [name, value] : values) {
    bool known = false;
    for (const ParameterSpec& spec : info.parameters) known = known || spec.name == name;
    if (!known) {
      std::string names;
      for (const ParameterSpec& spec : info.parameters) names += (names.empty() ? "" : ", ") + spec.name;
      throw InvalidInput("effects." + info.name + "." + name,
                         "unknown parameter; " + info.name + " takes: " + names);
    }
  }
  for (const ParameterSpec& spec : info.parameters) {
    const auto given = values.find(spec.name);
    const double value = given == values.end() ? spec.default_value : given->second;
    require_in_range("effects." + info.name + "." + spec.name, value, spec.lower, spec.upper);
    values_.push_back(value);
  }
}

void Effect::adjust_outputs_in_history_at(std::span<const RecordedSample> recording, std::span<const std::size_t> rows,
                                          std::span<SensorMoments> moments) const {
  for (std::size_t k = 0; k < rows.size(); ++k) adjust_outputs_in_history(InputHistory(recording, rows[k]), moments[k]);
}

bool has_input(const MeasurementSample& sample, OptionalInput input) {
  switch (input) {
    case OptionalInput::speed: return sample.speed_rpm.has_value();
    case OptionalInput::temperature: return sample.temperature_c.has_value();
    case OptionalInput::rotation_phase: return sample.rotation_phase_rad.has_value();
  }
  return false;
}

double Effect::value(const std::string& parameter) const {
  for (std::size_t i = 0; i < info_.parameters.size(); ++i) {
    if (info_.parameters[i].name == parameter) return values_[i];
  }
  throw InvalidInput("effects." + info_.name + "." + parameter, "no such parameter");
}

bool Effect::neutral() const {
  if (values_.empty()) return false;  // a switch (no parameters) changes the model by being there
  for (std::size_t i = 0; i < values_.size(); ++i) {
    if (values_[i] != info_.parameters[i].neutral) return false;
  }
  return true;
}

std::pair<double, double> plausible_range(const ParameterSpec& spec, double jam_angle_rad) {
  const double scale = spec.plausible.scale == RangeScale::jam_angle ? jam_angle_rad : 1.0;
  const double lower = std::isfinite(spec.plausible.lower) ? spec.plausible.lower * scale : spec.lower;
  const double upper = std::isfinite(spec.plausible.upper) ? spec.plausible.upper * scale : spec.upper;
  return {std::clamp(lower, spec.lower, spec.upper), std::clamp(upper, spec.lower, spec.upper)};
}

void add_misalignment(double zeta_rad, double beta_rad, OperatingPoint& point) {
  const double y = point.misalignment_rad * std::cos(point.direction_rad) + zeta_rad * std::cos(beta_rad);
  const double z = point.misalignment_rad * std::sin(point.direction_rad) + zeta_rad * std::sin(beta_rad);
  point.misalignment_rad = std::hypot(y, z);
  // Keep the measured direction when the sum vanishes: any direction is then right.
  if (point.misalignment_rad > 0.0) point.direction_rad = std::atan2(z, y);
}

double wrap_periodic(double value, double period) {
  if (!(period > 0.0)) return value;
  double w = std::remainder(value, period);  // in [-period/2, period/2]
  if (w <= -period / 2.0) w += period;
  return w;
}

}  // namespace gc
