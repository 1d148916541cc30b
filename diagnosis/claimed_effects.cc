#include "diagnosis/claimed_effects.h"

#include "core/effects/expression.h"

namespace gc {

std::optional<EffectRegistration> registration_for(const Effect& effect, const DiagnosisSettings& settings) {
  if (const auto members = effect.members(); !members.empty()) {
    std::vector<EffectRegistration> parts;
    for (const auto& m : members) {
      const std::optional<EffectRegistration> part = registration_for(*m, settings);
      if (!part) return std::nullopt;
      parts.push_back(*part);
    }
    return joint_registration(parts);
  }
  if (effect.name() == kExpressionEffect) {
    std::vector<std::string> terms;
    for (const ParameterSpec& p : effect.info().parameters) terms.push_back(p.name);
    return expression_registration(terms);
  }
  for (const EffectRegistration& r : settings.library) if (r.info->name == effect.name()) return r;
  return std::nullopt;
}

std::optional<JointEffect> joint_of(const std::vector<std::shared_ptr<const Effect>>& effects,
                                    const DiagnosisSettings& settings) {
  std::vector<EffectRegistration> registrations;
  for (const auto& effect : effects) {
    const std::optional<EffectRegistration> registration = registration_for(*effect, settings);
    if (!registration || registration->info->parameters.empty()) return std::nullopt;
    registrations.push_back(*registration);
  }
  const EffectRegistration joint = joint_registration(registrations);
  return JointEffect(*joint.info, joint_values(effects), registrations);
}

std::vector<std::string> claimed_names(const Effect& effect) {
  std::vector<std::string> names;
  for (const auto& m : effect.members()) names.push_back(m->name());
  if (names.empty()) names.push_back(effect.name());
  return names;
}

std::vector<std::shared_ptr<const Effect>> claimed_effects(const std::shared_ptr<const Effect>& effect) {
  std::vector<std::shared_ptr<const Effect>> members = effect->members();
  return members.empty() ? std::vector<std::shared_ptr<const Effect>>{effect} : members;
}

}  // namespace gc
