// gearcoupling contact: tooth contact (eqs 5-22) and the most loaded tooth's stress.
#include <fmt/format.h>

#include "clients/cli/operating_point_flags.h"
#include "clients/cli/subcommand.h"
#include "analysis/table.h"
#include "codec/angle_units.h"
#include "codec/result_messages.h"

namespace gc::cli {

using analysis::Table;
using analysis::format_number;
using analysis::quantity_table;
namespace {

using codec::degrees_from_radians;

std::vector<FlagSpec> contact_flags() {
  std::vector<FlagSpec> flags = operating_point_flags(/*friction_used=*/false);
  append(flags, contact_option_flags());
  append(flags, calculator_flags());
  return flags;
}

void print_summary(std::string_view name, const OperatingPoint& point, const ToothContact& c,
                   std::FILE* out) {
  Table table = quantity_table();
  table.add_quantity("coupling", name, "");
  table.add_quantity("torque T", point.torque_nm, "N·m");
  table.add_quantity("misalignment zeta", degrees_from_radians(point.misalignment_rad), "deg");
  table.add_quantity("direction beta", degrees_from_radians(point.direction_rad), "deg");
  table.add_quantity("load-sharing ratio q (eq 22)", c.load_sharing.q, "-");
  table.add_quantity("iterations (eqs 20-22)", std::to_string(c.load_sharing.iterations), "-");
  table.add_quantity("total normal load P_t (eq 7)", c.total_normal_load_n, "N");
  table.add_quantity("mean tooth load P_t' (eq 20)", c.mean_tooth_load_n, "N");
  table.add_quantity("peak tooth load P_i (eq 20)", c.peak_tooth_load_n, "N");
  table.add_quantity("elastic deformation z_e (eq 10)", c.elastic_deformation_m, "m");
  table.add_quantity("max separation z_o (eq 11)", c.max_separation_m, "m");
  table.add_quantity("offset alpha (eq 13)", degrees_from_radians(c.offset_alpha_rad), "deg");
  table.add_quantity("max contact offset F_i (eq 15)", c.max_contact_offset_m, "m");
  table.add_quantity("z'' axis from z'", degrees_from_radians(c.z_axis_angle_rad), "deg");
  table.add_quantity("teeth in contact", std::to_string(c.teeth_in_contact), "-");
  table.add_quantity("most loaded tooth j", std::to_string(c.max_load_tooth), "-");
  table.add_quantity("max tooth load", c.max_tooth_load_n, "N");
  table.add_quantity("sum of tooth loads", c.sum_tooth_loads_n, "N");
  table.add_quantity("edge loaded (eq 19)", c.edge_loaded ? "yes" : "no", "");
  table.add_quantity("contact stress", c.max_stress.contact_stress_pa, "Pa");
  table.add_quantity("bending stress", c.max_stress.bending_stress_pa, "Pa");
  table.add_quantity("contact safety factor", c.max_stress.contact_safety_factor, "-");
  table.add_quantity("bending safety factor", c.max_stress.bending_safety_factor, "-");
  table.print(out);
}

void print_teeth(const ToothContact& c, std::FILE* out) {
  Table table({"tooth j", "angle [deg]", "load P_d [N]", "offset F_d [m]", "deformation [m]",
               "contact length F_c [m]", "zone begin [m]", "zone end [m]"});
  for (std::size_t j = 0; j < c.teeth.size(); ++j) {
    const ToothLoad& t = c.teeth[j];
    table.add_row({std::to_string(j), format_number(degrees_from_radians(t.angle_rad)),
                   format_number(t.load_n), format_number(t.contact_offset_m),
                   format_number(t.deformation_m), format_number(t.contact_length_m),
                   format_number(t.zone_begin_m), format_number(t.zone_end_m)});
  }
  table.print(out);
}

int run_contact(const Flags& flags, const Calculator& calculator, std::FILE* out) {
  const std::string& coupling = flags.text("coupling");
  const OperatingPoint point = operating_point_from(flags);
  const ToothContact contact =
      calculator.tooth_contact(coupling, point, contact_options_from(flags));
  const std::string name = calculator.coupling_name(coupling);
  if (flags.enabled("json")) {
    print_json(codec::to_message(name, point, contact), out);
    return 0;
  }
  print_summary(name, point, contact, out);
  fmt::print(out, "\nEvery tooth (eqs 9, 16-19; slice loads of eq 14 with --json):\n");
  print_teeth(contact, out);
  return 0;
}

}  // namespace

const Subcommand& contact_subcommand() {
  static const Subcommand subcommand{
      "contact",
      "Tooth contact at one load case (eqs 5-22).\n"
      "Load sharing, the load, contact offset, deformation and contact zone of every tooth,\n"
      "and the most loaded tooth's contact and bending stress.",
      contact_flags, run_contact};
  return subcommand;
}

}  // namespace gc::cli
