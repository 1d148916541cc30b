#include <vector>

#include "clients/cli/subcommand.h"

namespace gc::cli {

std::span<const Subcommand* const> subcommands() {
  static const std::vector<const Subcommand*> all = {
      &contact_subcommand(),          &jam_angle_subcommand(), &moments_subcommand(),
      &restoring_torque_subcommand(), &friction_subcommand(),  &batch_subcommand(),
      &synth_subcommand(),            &validate_subcommand(),  &diagnose_subcommand(),
#ifdef GC_CLI_LIVE
      &replay_subcommand(),           &record_subcommand(),    &swap_model_subcommand(),
      &status_subcommand(),           &proposals_subcommand(),
#endif
  };
  return all;
}

}  // namespace gc::cli
