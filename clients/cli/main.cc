// gearcoupling: the command-line client. Picks the subcommand, parses its flags, runs it on the
// in-process calculator and turns every error into a one-line message and an exit code:
// 0 success, 1 failure after running (a batch row, an output file), 2 bad input.
#include <array>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>

#include <fmt/format.h>

#include "clients/cli/make_calculator.h"
#include "analysis/format_error.h"
#include "analysis/input_names.h"
#include "clients/cli/subcommand.h"
#include "core/model_error.h"

namespace gc::cli {

using analysis::describe_input_error;
using analysis::flag_for_field;
namespace {

constexpr int kBadInput = 2;

std::vector<const Subcommand*> subcommands() {
  return {&contact_subcommand(),          &jam_angle_subcommand(), &moments_subcommand(),
          &restoring_torque_subcommand(), &friction_subcommand(),  &batch_subcommand(),
          &synth_subcommand(),            &validate_subcommand(),  &diagnose_subcommand(),
#ifdef GC_CLI_LIVE
          &replay_subcommand(),           &record_subcommand(),    &swap_model_subcommand(),
          &status_subcommand(),
#endif
  };
}

std::string overview() {
  std::string text =
      "usage: gearcoupling <subcommand> [flags]\n\n"
      "Crowned-tooth gear coupling model (Guo et al.). Subcommands:\n";
  for (const Subcommand* subcommand : subcommands()) {
    const std::string_view first_line =
        subcommand->summary.substr(0, subcommand->summary.find('\n'));
    text += fmt::format("  {:<18} {}\n", subcommand->name, first_line);
  }
  return text + "\n'gearcoupling <subcommand> --help' lists its flags.\n";
}

const Subcommand* find_subcommand(std::string_view name) {
  for (const Subcommand* subcommand : subcommands()) {
    if (subcommand->name == name) return subcommand;
  }
  return nullptr;
}

std::vector<FlagSpec> all_flags(const Subcommand& subcommand) {
  std::vector<FlagSpec> flags = subcommand.flags();
  for (FlagSpec& flag : common_flags()) flags.push_back(std::move(flag));
  return flags;
}

// The core's message, led by the flag and value the user typed when a flag set the field.
std::string describe(const InvalidInput& error, const Flags& flags) {
  const std::string_view flag = flag_for_field(error.field());
  if (flag.empty()) return error.what();
  for (const FlagSpec& spec : flags.specs()) {
    if (spec.name == flag) return describe_input_error(error, "--" + spec.name, flags.text(flag));
  }
  return error.what();
}

int run(const Subcommand& subcommand, std::span<const char* const> args) {
  const auto fail = [&](const std::string& message) {
    fmt::print(stderr, "gearcoupling {}: error: {}\n", subcommand.name, message);
    return kBadInput;
  };
  std::optional<Flags> flags;
  try {
    flags.emplace(all_flags(subcommand), args);
    if (flags->help_requested()) {
      fmt::print("{}", usage_text(subcommand.name, subcommand.summary, flags->specs()));
      return 0;
    }
    const std::unique_ptr<Calculator> calculator = make_calculator(*flags);
    return subcommand.run(*flags, *calculator, stdout);
  } catch (const UsageError& error) {
    return fail(error.what());
  } catch (const analysis::FormatError& error) {
    return fail(error.what());
  } catch (const InvalidInput& error) {
    return fail(flags ? describe(error, *flags) : error.what());
  } catch (const NotConverged& error) {
    return fail(std::string(error.what()) + " (see --tolerance and --max-iterations)");
  } catch (const ModelError& error) {
    return fail(error.what());
  } catch (const std::exception& error) {
    fmt::print(stderr, "gearcoupling {}: failed: {}\n", subcommand.name, error.what());
    return 1;
  }
}

}  // namespace
}  // namespace gc::cli

int main(int argc, char** argv) {
  using namespace gc::cli;
  const std::span<const char* const> args(argv, static_cast<std::size_t>(argc));
  if (args.size() < 2 || std::string_view(args[1]) == "--help" ||
      std::string_view(args[1]) == "-h") {
    fmt::print(args.size() < 2 ? stderr : stdout, "{}", overview());
    return args.size() < 2 ? kBadInput : 0;
  }
  const Subcommand* subcommand = find_subcommand(args[1]);
  if (subcommand == nullptr) {
    std::string names;
    for (const Subcommand* known : subcommands()) {
      names += (names.empty() ? "" : ", ") + std::string(known->name);
    }
    fmt::print(stderr, "gearcoupling: error: unknown subcommand '{}' (one of {}; see --help)\n",
               args[1], names);
    return kBadInput;
  }
  return run(*subcommand, args.subspan(2));
}
