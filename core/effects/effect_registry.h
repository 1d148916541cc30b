// The effects library by name. Adding an effect: write one class in one file under
// core/effects/ with a `<name>_effect()` registration function, and add one line to
// effect_registry.cc (docs/adding-an-effect.md).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/effects/effect.h"

namespace gc {

struct EffectRegistration {
  const EffectInfo* info;
  std::function<std::shared_ptr<const Effect>(const ParameterValues&)> make;
};

/// Every registered effect, in a fixed order. Built once, immutable.
const std::vector<EffectRegistration>& effect_registry();

/// Throws InvalidInput naming "effects.<name>" for an unknown name (listing the known ones), or
/// naming the parameter for a bad value.
std::shared_ptr<const Effect> make_effect(const std::string& name,
                                          const ParameterValues& values = {});
const EffectInfo& effect_info(const std::string& name);

}  // namespace gc
