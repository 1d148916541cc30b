#include "core/effects/effect_registry.h"

#include "core/effects/expression.h"
#include "core/model_error.h"

namespace gc {

// One line per effect: each is defined in its own file.
EffectRegistration friction_effect();
EffectRegistration self_weight_effect();
EffectRegistration pressure_angle_rotation_effect();
EffectRegistration assembly_misalignment_effect();
EffectRegistration eccentricity_effect();
EffectRegistration compliance_effect();
EffectRegistration spacing_errors_effect();
EffectRegistration channel_gain_offset_effect();
EffectRegistration hysteresis_effect();
EffectRegistration misalignment_scale_effect();
EffectRegistration continuous_quarter_sums_effect();
EffectRegistration moment_delay_effect();
EffectRegistration torque_calibration_effect();
EffectRegistration thermal_misalignment_effect();

const std::vector<EffectRegistration>& effect_registry() {
  static const std::vector<EffectRegistration> registry = {
      friction_effect(),      self_weight_effect(),   pressure_angle_rotation_effect(),
      assembly_misalignment_effect(), eccentricity_effect(), compliance_effect(),
      spacing_errors_effect(), channel_gain_offset_effect(), hysteresis_effect(),
      misalignment_scale_effect(),        continuous_quarter_sums_effect(), moment_delay_effect(),
      torque_calibration_effect(), thermal_misalignment_effect(),
      // The formula of docs/diagnosis.md: its parameters are the terms it is given.
      {&expression_info({}), [](const ParameterValues& values) { return make_expression(values); }},
  };
  return registry;
}

namespace {

const EffectRegistration& find(const std::string& name) {
  std::string known;
  for (const EffectRegistration& r : effect_registry()) {
    if (r.info->name == name) return r;
    known += (known.empty() ? "" : ", ") + r.info->name;
  }
  throw InvalidInput("effects." + name, "unknown effect; the library has: " + known);
}

}  // namespace

std::shared_ptr<const Effect> make_effect(const std::string& name, const ParameterValues& values) {
  return find(name).make(values);
}

const EffectInfo& effect_info(const std::string& name) { return *find(name).info; }

}  // namespace gc
