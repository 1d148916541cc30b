// Helper for effect files: the registration of an Effect subclass constructed from values.
#pragma once

#include "core/effects/effect_registry.h"

namespace gc {

template <typename EffectClass>
EffectRegistration register_effect(const EffectInfo& info) {
  return {&info, [](const ParameterValues& values) -> std::shared_ptr<const Effect> {
            return std::make_shared<const EffectClass>(values);
          }};
}

}  // namespace gc
