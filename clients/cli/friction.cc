// gearcoupling friction: the friction coefficient from test-cell measurements (eqs 1-4).
#include "clients/cli/subcommand.h"
#include "analysis/table.h"
#include "codec/angle_units.h"
#include "codec/result_messages.h"

namespace gc::cli {

using analysis::Table;
using analysis::quantity_table;
namespace {

std::vector<FlagSpec> friction_flags() {
  std::vector<FlagSpec> flags = {
      {"torque-nm", "N·m", "measured torque T [N·m], > 0", std::nullopt, false, '\0', {"torque"}},
      {"misalignment-deg", "deg", "measured misalignment zeta [deg]", std::nullopt},
      {"direction-deg", "deg", "direction beta of the misalignment axis [deg]", "0"},
      {"msy-nm", "N·m", "measured sensor moment M_sy' [N·m]", std::nullopt, false, '\0', {"msy"}},
      {"msz-nm", "N·m", "measured sensor moment M_sz' [N·m]", std::nullopt, false, '\0', {"msz"}},
  };
  append(flags, calculator_flags());
  return flags;
}

int run_friction(const Flags& flags, const Calculator& calculator, std::FILE* out) {
  const std::string& coupling = flags.text("coupling");
  const FrictionMeasurement measurement{
      .torque_nm = flags.number("torque-nm"),
      .misalignment_rad = codec::radians_from_degrees(flags.number("misalignment-deg")),
      .direction_rad = codec::radians_from_degrees(flags.number("direction-deg")),
      .sensor_moment_y_nm = flags.number("msy-nm"),
      .sensor_moment_z_nm = flags.number("msz-nm")};
  const FrictionEstimate estimate = calculator.estimate_friction(coupling, measurement);
  const std::string name = calculator.coupling_name(coupling);
  if (flags.enabled("json")) {
    print_json(codec::to_message(name, measurement, estimate), out);
    return 0;
  }
  Table table = quantity_table();
  table.add_quantity("coupling", name, "");
  table.add_quantity("torque T", measurement.torque_nm, "N·m");
  table.add_quantity("misalignment zeta",
                     codec::degrees_from_radians(measurement.misalignment_rad), "deg");
  table.add_quantity("direction beta", codec::degrees_from_radians(measurement.direction_rad),
                     "deg");
  table.add_quantity("sensor M_sy'", measurement.sensor_moment_y_nm, "N·m");
  table.add_quantity("sensor M_sz'", measurement.sensor_moment_z_nm, "N·m");
  table.add_quantity("M_tz'' (eq 3)", estimate.moment_z_dd_nm, "N·m");
  table.add_quantity("friction coefficient mu (eq 4)", estimate.friction_coefficient, "-");
  table.print(out);
  return 0;
}

}  // namespace

const Subcommand& friction_subcommand() {
  static const Subcommand subcommand{
      "friction",
      "Friction coefficient from test-cell measurements (eqs 1-4).\n"
      "From measured torque, misalignment, direction and sensor moments; an approximation of\n"
      "eqs 42-47, see docs/model.md.",
      friction_flags, run_friction};
  return subcommand;
}

}  // namespace gc::cli
