// A proposal's fitted parameter as an operator reads it, in the words diagnose prints: the value
// with an SI prefix (mrad, µrad, kN·m), the standard error under the value's prefix, a rate per
// kelvin as per °C. The page showed "0.005113 ± 2.2e-5 rad" where diagnose said mrad (issue 39).
#pragma once

#include <string>

#include "idl/live_status.pb.h"

namespace gc::status {

/// "eccentricity.eccentric_misalignment_rad = 1.52 mrad ± 0.0220 mrad", "(held)" for a held
/// one, "(implausible)" outside its plausible range.
std::string parameter_display(const ::gearcoupling::v1::ProposedParameterRecord& p);

}  // namespace gc::status
