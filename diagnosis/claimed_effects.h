// The effects a diagnosis claims, as it refits and names them: the registration that refits one
// (the library's, an expression over its own terms, or a joint of its members' registrations),
// several as one effect to refit jointly, and what a claim of several fitted as one stands for.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/effects/effect.h"
#include "core/effects/effect_registry.h"
#include "core/effects/joint_effect.h"
#include "diagnosis/diagnose.h"

namespace gc {

/// The registration that refits `effect`: the library's, or an expression over its own terms.
std::optional<EffectRegistration> registration_for(const Effect& effect, const DiagnosisSettings& settings);

/// `effects` as one effect to refit jointly; nullopt when one has no registration or no parameter.
std::optional<JointEffect> joint_of(const std::vector<std::shared_ptr<const Effect>>& effects,
                                    const DiagnosisSettings& settings);

/// The names a claimed effect stands for: its own, or its members' when several were fitted as one.
std::vector<std::string> claimed_names(const Effect& effect);

/// The effects a claim puts in the model: itself, or its members.
std::vector<std::shared_ptr<const Effect>> claimed_effects(const std::shared_ptr<const Effect>& effect);

}  // namespace gc
