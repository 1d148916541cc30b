#include "clients/cli/operating_point_flags.h"

#include <limits>

#include "analysis/number_text.h"
#include "codec/angle_units.h"

namespace gc::cli {

using analysis::append_number;
namespace {

std::string shortest(double value) {
  std::string text;
  append_number(text, value);
  return text;
}

}  // namespace

std::vector<FlagSpec> operating_point_flags(bool friction_used) {
  std::vector<FlagSpec> flags = {
      {"torque-nm", "N·m", "transmitted torque T [N·m], > 0", std::nullopt, false, '\0',
       {"torque"}},
      {"misalignment-deg", "deg", "angular misalignment zeta [deg], below the jam angle",
       std::nullopt},
      {"direction-deg", "deg", "direction beta of the misalignment axis [deg]", "0"},
  };
  if (friction_used) {
    flags.push_back(
        {"mu", "number", "tooth sliding friction coefficient mu [-], 0..1", std::nullopt});
  } else {
    flags.push_back(
        {"mu", "number", "friction coefficient mu [-]; not used by this calculation", "0"});
  }
  return flags;
}

std::vector<FlagSpec> contact_option_flags() {
  const ContactOptions defaults;
  return {
      {"tolerance", "number", "load-sharing iteration tolerance on q, eqs 20-22 [-]",
       shortest(defaults.load_sharing.tolerance)},
      {"max-iterations", "count", "load-sharing iteration limit",
       std::to_string(defaults.load_sharing.max_iterations)},
      {"slices", "count", "facewidth slices per contact zone N_s, even (eq 14)",
       std::to_string(defaults.slices)},
  };
}

OperatingPoint operating_point_from(const Flags& flags) {
  return {.torque_nm = flags.number("torque-nm"),
          .misalignment_rad = codec::radians_from_degrees(flags.number("misalignment-deg")),
          .direction_rad = codec::radians_from_degrees(flags.number("direction-deg")),
          .friction_coefficient = flags.number("mu")};
}

ContactOptions contact_options_from(const Flags& flags) {
  ContactOptions options;
  options.load_sharing.tolerance = flags.number("tolerance");
  // Only whether they are ints is checked here; the core checks the ranges and names the field.
  constexpr int kMin = std::numeric_limits<int>::min();
  constexpr int kMax = std::numeric_limits<int>::max();
  options.load_sharing.max_iterations = flags.integer("max-iterations", kMin, kMax);
  options.slices = flags.integer("slices", kMin, kMax);
  return options;
}

}  // namespace gc::cli
