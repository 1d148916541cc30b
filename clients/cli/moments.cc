// gearcoupling moments: coupling-induced bending moments (eqs 36-48).
#include "clients/cli/operating_point_flags.h"
#include "clients/cli/subcommand.h"
#include "analysis/table.h"
#include "codec/angle_units.h"
#include "codec/result_messages.h"

namespace gc::cli {

using analysis::Table;
using analysis::quantity_table;
namespace {

using codec::degrees_from_radians;

std::vector<FlagSpec> moments_flags() {
  std::vector<FlagSpec> flags = operating_point_flags(/*friction_used=*/true);
  append(flags, contact_option_flags());
  append(flags, calculator_flags());
  return flags;
}

int run_moments(const Flags& flags, const Calculator& calculator, std::FILE* out) {
  const std::string& coupling = flags.text("coupling");
  const OperatingPoint point = operating_point_from(flags);
  const LoadCase result = calculator.load_case(coupling, point, contact_options_from(flags));
  const std::string name = calculator.coupling_name(coupling);
  if (flags.enabled("json")) {
    print_json(codec::to_message(name, point, result.contact, result.moments), out);
    return 0;
  }
  const InducedMoments& m = result.moments;
  Table table = quantity_table();
  table.add_quantity("coupling", name, "");
  table.add_quantity("torque T", point.torque_nm, "N·m");
  table.add_quantity("misalignment zeta", degrees_from_radians(point.misalignment_rad), "deg");
  table.add_quantity("direction beta", degrees_from_radians(point.direction_rad), "deg");
  table.add_quantity("friction mu", point.friction_coefficient, "-");
  table.add_quantity("load-sharing ratio q (eq 22)", result.contact.load_sharing.q, "-");
  table.add_quantity("teeth in contact", std::to_string(result.contact.teeth_in_contact), "-");
  table.add_quantity("max tooth load", result.contact.max_tooth_load_n, "N");
  table.add_quantity("M_y'' (eq 43)", m.moment_y_dd_nm, "N·m");
  table.add_quantity("M_z'' (eq 42)", m.moment_z_dd_nm, "N·m");
  table.add_quantity("M_y' (eq 46)", m.moment_y_nm, "N·m");
  table.add_quantity("M_z' (eq 47)", m.moment_z_nm, "N·m");
  table.add_quantity("sensor M_sy' (eq 48)", m.sensor_moment_y_nm, "N·m");
  table.add_quantity("sensor M_sz' (eq 48)", m.sensor_moment_z_nm, "N·m");
  table.add_quantity("self-weight moment (eq 48)", m.self_weight_moment_nm, "N·m");
  table.add_quantity("magnitude |M'|", m.magnitude_nm, "N·m");
  table.add_quantity("direction of M'", degrees_from_radians(m.direction_rad), "deg");
  table.add_quantity("teeth summed (eqs 42-43)", std::to_string(m.teeth_summed), "-");
  table.print(out);
  return 0;
}

}  // namespace

const Subcommand& moments_subcommand() {
  static const Subcommand subcommand{
      "moments",
      "Coupling-induced bending moments at one load case (eqs 36-48).\n"
      "In the double-prime frame, the coupling frame and at the sensors, with the self-weight\n"
      "terms.",
      moments_flags, run_moments};
  return subcommand;
}

}  // namespace gc::cli
