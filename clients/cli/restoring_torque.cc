// gearcoupling restoring-torque: the torque that lifts and centres the hub (eqs 49-53).
#include "clients/cli/subcommand.h"
#include "analysis/table.h"
#include "codec/result_messages.h"

namespace gc::cli {

using analysis::Table;
using analysis::quantity_table;
namespace {

int run_restoring_torque(const Flags& flags, const Calculator& calculator, std::FILE* out) {
  const std::string& coupling = flags.text("coupling");
  const RestoringTorque torque = calculator.restoring_torque(coupling);
  const std::string name = calculator.coupling_name(coupling);
  if (flags.enabled("json")) {
    print_json(codec::to_message(name, torque), out);
    return 0;
  }
  Table table = quantity_table();
  table.add_quantity("coupling", name, "");
  table.add_quantity("restoring torque T_m", torque.torque_nm, "N·m");
  table.add_quantity("root contact", to_string(torque.contact), "");
  table.add_quantity("teeth in contact N_c", std::to_string(torque.teeth_in_contact), "-");
  table.add_quantity("accessible clearance Delta_c (eq 49)", torque.accessible_clearance_m, "m");
  table.add_quantity("design root clearance Delta_r", torque.design_clearance_m, "m");
  table.add_quantity("supported weight W_c + 0.5 W_sh", torque.supported_weight_n, "N");
  table.add_quantity("hub sag W / (2 N C)", torque.sag_m, "m");
  table.print(out);
  return 0;
}

}  // namespace

const Subcommand& restoring_torque_subcommand() {
  static const Subcommand subcommand{
      "restoring-torque",
      "Torque that lifts the hub off the sleeve and centres it (eqs 49-53).\n"
      "With the root-clearance case the geometry selects and the teeth in contact.",
      [] { return calculator_flags(); }, run_restoring_torque};
  return subcommand;
}

}  // namespace gc::cli
