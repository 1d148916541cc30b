// --add EFFECT[=parameter=value,...]: one effect of the library with parameters in SI, e.g.
// "hysteresis=lag_rad=0.0006" or "friction=mu0=0.06,mu_low_torque=0.03". Parameters not given
// take their defaults (core/effects/).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "core/effects/effect.h"

namespace gc::analysis {

/// Throws FormatError for a malformed spec or a value that is not a number, gc::InvalidInput
/// naming "effects.<name>[.<parameter>]" for an unknown effect or parameter or a value out of
/// its bounds.
std::shared_ptr<const Effect> parse_effect_spec(std::string_view spec);

/// The spec parse_effect_spec reads back to `effect` to 6 significant digits: "name" or
/// "name=p=v,..." with every parameter in SI (what diagnose prints for --add). Six digits are
/// what a fit determines and reproduce a validation; all 17 differ between CPUs in the last ones.
std::string effect_spec_text(const Effect& effect);

}  // namespace gc::analysis
