// The flags that state a load case (torque, misalignment, direction, friction) and the contact
// solver's options, shared by every subcommand that computes one.
#pragma once

#include <vector>

#include "clients/cli/command_line.h"
#include "core/operating_point.h"
#include "core/tooth_contact.h"

namespace gc::cli {

/// --torque-nm, --misalignment-deg, --direction-deg and --mu. `friction_used` says whether the
/// calculation reads mu: then --mu is required, otherwise it defaults to 0 and is ignored.
std::vector<FlagSpec> operating_point_flags(bool friction_used);

/// --tolerance, --max-iterations, --slices with the core's defaults.
std::vector<FlagSpec> contact_option_flags();

/// Degrees converted to radians; ranges are the core's to check.
OperatingPoint operating_point_from(const Flags& flags);
ContactOptions contact_options_from(const Flags& flags);

}  // namespace gc::cli
