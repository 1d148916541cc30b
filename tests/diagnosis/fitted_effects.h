// Lookups for the tests of effect fits: an effect's registration by its name, and a fitted
// parameter's value by its name.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/effects/effect_registry.h"
#include "diagnosis/effect_fit.h"

namespace gc::testing {

inline const EffectRegistration& registration(const std::string& name) {
  static const std::vector<EffectRegistration> registry = effect_registry();
  for (const EffectRegistration& r : registry) if (r.info->name == name) return r;
  throw std::logic_error("no " + name + " in the registry");
}

/// The fitted value of `name` [its unit].
inline double fitted_value(const EffectFit& fit, const std::string& name) {
  for (const ParameterEstimate& p : fit.parameters) if (p.name == name) return p.value;
  throw std::logic_error("no " + name + " in the fit");
}

}  // namespace gc::testing
