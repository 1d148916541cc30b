// A subcommand of gearcoupling: its name, what it does, its flags and how it runs. To add one:
// a file <name>.cc defining <name>_subcommand() (flags: its own, plus calculator_flags() when it
// computes on a Calculator, or catalogue_flag()/json_flag() when it does not), its declaration
// below and its entry in subcommands.cc. main.cc parses the flags with CLI11, prints the help
// and turns errors into exit codes; bash_completion.cc completes the same flags.
#pragma once

#include <cstdio>
#include <span>
#include <string_view>
#include <vector>

#include <google/protobuf/message.h>

#include "calculators/calculator.h"
#include "clients/cli/command_line.h"

namespace gc::cli {

using analysis::LoadCase;
using calculators::Calculator;
using calculators::JamAngleReport;

struct Subcommand {
  std::string_view name;
  std::string_view summary;
  std::vector<FlagSpec> (*flags)();  ///< every flag it takes, shared ones included
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
const Subcommand& proposals_subcommand();

/// Every subcommand, in the order of the overview.
std::span<const Subcommand* const> subcommands();

/// --catalogue DIR: the directory of *.textproto couplings.
FlagSpec catalogue_flag();
/// --json: the result as the codec's JSON.
FlagSpec json_flag();
/// --domain N: a DDS domain id, 0..protocol::kMaxDomainId (default 0), described by `help`.
FlagSpec domain_flag(std::string help);
/// The --domain flag's value; UsageError outside 0..protocol::kMaxDomainId.
int domain_from(const Flags& flags);
/// --coupling, --catalogue, --remote, --domain, --timeout-s, --client-id-prefix, and --json
/// when `json`: the flags of a subcommand that computes on a Calculator (make_calculator.h).
std::vector<FlagSpec> calculator_flags(bool json = true);
/// --coupling, --remote, --domain, --timeout-s, --client-id-prefix refused, saying why: for a
/// subcommand that computes in process from a model file (validate, diagnose, synth).
std::vector<FlagSpec> refused_calculator_flags(std::string_view subcommand);

/// --domain N: the DDS domain of the live test cell (replay, record, swap-model).
FlagSpec live_domain_flag();

/// Appends `more` to `flags`.
void append(std::vector<FlagSpec>& flags, std::vector<FlagSpec> more);

/// Prints `message` as the codec's JSON (codec/result_json.h).
void print_json(const google::protobuf::Message& message, std::FILE* out);

}  // namespace gc::cli
