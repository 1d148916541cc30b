// gearcoupling jam-angle: the three criteria of eqs 23-35 and the one that governs.
#include "clients/cli/subcommand.h"
#include "analysis/table.h"
#include "codec/angle_units.h"
#include "codec/result_messages.h"

namespace gc::cli {

using analysis::Table;
using analysis::quantity_table;
namespace {

using codec::degrees_from_radians;

int run_jam_angle(const Flags& flags, const Calculator& calculator, std::FILE* out) {
  const std::string& coupling = flags.text("coupling");
  const JamAngleReport report = calculator.jam_angle(coupling);
  const std::string name = calculator.coupling_name(coupling);
  if (flags.enabled("json")) {
    print_json(codec::to_message(name, report.jam, report.crown_radius_m,
                                 report.crown_radius_derived),
               out);
    return 0;
  }
  const JamAngle& jam = report.jam;
  Table table = quantity_table();
  table.add_quantity("coupling", name, "");
  table.add_quantity("jam angle xi (eq 35)", degrees_from_radians(jam.angle_rad), "deg");
  table.add_quantity("governing criterion", to_string(jam.governing), "");
  if (jam.both_flanks_rad) {
    table.add_quantity("both flanks (eq 29)", degrees_from_radians(*jam.both_flanks_rad), "deg");
  } else {
    table.add_quantity("both flanks (eq 29)", "no root below the facewidth limit", "");
  }
  table.add_quantity("facewidth (eq 30)", degrees_from_radians(jam.facewidth_rad), "deg");
  table.add_quantity("radial (eq 34)", degrees_from_radians(jam.radial_rad), "deg");
  table.add_quantity(report.crown_radius_derived ? "crown radius R_F (from lead modification)"
                                                 : "crown radius R_F (given)",
                     report.crown_radius_m, "m");
  table.print(out);
  return 0;
}

}  // namespace

const Subcommand& jam_angle_subcommand() {
  static const Subcommand subcommand{
      "jam-angle",
      "Jam angle and its three criteria (eqs 23-35).\n"
      "The both-flanks, facewidth and radial criteria; the smallest governs.",
      [] { return calculator_flags(); }, run_jam_angle};
  return subcommand;
}

}  // namespace gc::cli
