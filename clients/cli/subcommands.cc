#include <array>

#include "clients/cli/subcommand.h"

namespace gc::cli {

std::span<const Subcommand* const> subcommands() {
  static const std::array<const Subcommand*, 9> all = {
      &contact_subcommand(),          &jam_angle_subcommand(), &moments_subcommand(),
      &restoring_torque_subcommand(), &friction_subcommand(),  &batch_subcommand(),
      &synth_subcommand(),            &validate_subcommand(),  &diagnose_subcommand()};
  return all;
}

}  // namespace gc::cli
