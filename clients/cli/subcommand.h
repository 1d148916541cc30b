// A subcommand of gearcoupling: its name, what it does, its own flags and how it runs. main.cc
// adds the flags every subcommand shares (common_flags) and turns errors into exit codes.
#pragma once

#include <cstdio>
#include <string_view>
#include <vector>

#include <google/protobuf/message.h>

#include "clients/cli/calculator.h"
#include "clients/cli/command_line.h"

namespace gc::cli {

struct Subcommand {
  std::string_view name;
  std::string_view summary;
  std::vector<FlagSpec> (*flags)();
  /// Returns the exit code; throws UsageError or gc::ModelError for bad input.
  int (*run)(const Flags& flags, const Calculator& calculator, std::FILE* out);
};

const Subcommand& contact_subcommand();
const Subcommand& jam_angle_subcommand();
const Subcommand& moments_subcommand();
const Subcommand& restoring_torque_subcommand();
const Subcommand& friction_subcommand();
const Subcommand& batch_subcommand();
const Subcommand& synth_subcommand();
const Subcommand& validate_subcommand();
const Subcommand& diagnose_subcommand();
const Subcommand& replay_subcommand();
const Subcommand& record_subcommand();
const Subcommand& swap_model_subcommand();
const Subcommand& status_subcommand();

/// --coupling, --catalog and --json.
std::vector<FlagSpec> common_flags();

/// Prints `message` as the codec's JSON (codec/result_json.h).
void print_json(const google::protobuf::Message& message, std::FILE* out);

}  // namespace gc::cli
