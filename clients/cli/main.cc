// gearcoupling: the command-line client. CLI11 picks the subcommand and parses its flags (the
// tables of subcommand.h); the subcommand runs on the calculator the flags ask for; every error
// becomes a one-line message and an exit code: 0 success, 1 failure after running (a batch
// row, an output file), 2 bad input.
#include <cstdio>
#include <memory>
#include <span>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "analysis/format_error.h"
#include "analysis/input_names.h"
#include "clients/cli/bash_completion.h"
#include "clients/cli/make_calculator.h"
#include "clients/cli/model_flags.h"
#include "clients/cli/subcommand.h"
#include "codec/coupling_catalog.h"
#include "core/model_error.h"

namespace gc::cli {

using analysis::describe_input_error;
using analysis::flag_for_field;
namespace {

constexpr int kBadInput = 2;

std::string overview() {
  std::string text =
      "usage: gearcoupling <subcommand> [flags]\n\n"
      "Crowned-tooth gear coupling model (Guo et al.). Subcommands:\n";
  for (const Subcommand* subcommand : subcommands()) {
    const std::string_view first_line =
        subcommand->summary.substr(0, subcommand->summary.find('\n'));
    text += fmt::format("  {:<18} {}\n", subcommand->name, first_line);
  }
  return text +
         "\n'gearcoupling <subcommand> --help' lists its flags.\n"
         "--version prints the version; --bash-completion prints the bash completion script.\n";
}

bool is_subcommand(std::string_view name) {
  for (const Subcommand* subcommand : subcommands()) {
    if (subcommand->name == name) return true;
  }
  return false;
}

std::string subcommand_names() {
  std::string names;
  for (const Subcommand* known : subcommands()) {
    names += (names.empty() ? "" : ", ") + std::string(known->name);
  }
  return names;
}

// The core's message, led by the flag and value the user typed when a flag set the field.
std::string describe(const InvalidInput& error, const Flags& flags) {
  const std::string_view flag = flag_for_field(error.field());
  if (flag.empty() || !flags.has(flag)) return error.what();
  std::string text = describe_input_error(error, "--" + std::string(flag), flags.text(flag));
  if (analysis::refuses_negative_torque(error)) {
    text += analysis::negative_torque_hint("for a dyno that logs the drive torque negative, give "
                                           "--torque-nm its magnitude");
  }
  return text;
}

int run(const Subcommand& subcommand, const Flags& flags) {
  const auto fail = [&](const std::string& message) {
    fmt::print(stderr, "gearcoupling {}: error: {}\n", subcommand.name, message);
    return kBadInput;
  };
  try {
    flags.check();
    const std::unique_ptr<Calculator> calculator = make_calculator(flags);
    return subcommand.run(flags, *calculator, stdout);
  } catch (const UsageError& error) {
    return fail(error.what());
  } catch (const analysis::FormatError& error) {
    return fail(error.what());
  } catch (const InvalidInput& error) {
    return fail(describe(error, flags));
  } catch (const NotConverged& error) {
    return fail(std::string(error.what()) + " (see --tolerance and --max-iterations)");
  } catch (const ModelError& error) {
    return fail(error.what());
  } catch (const std::exception& error) {
    fmt::print(stderr, "gearcoupling {}: failed: {}\n", subcommand.name, error.what());
    return 1;
  }
}

// The top-level app with one CLI11 subcommand per Subcommand, each bound to its Flags.
struct CommandLine {
  CLI::App app{"Crowned-tooth gear coupling model (Guo et al.)", "gearcoupling"};
  std::vector<std::unique_ptr<Flags>> flags;  // parallel to subcommands()
  bool print_completion = false;
  std::string complete_names;   // --complete-names KIND, for the bash completion

  CommandLine() {
    app.set_version_flag("--version", "gearcoupling " GC_VERSION);
    app.add_flag("--bash-completion", print_completion, "print the bash completion script");
    // Hidden (no group): what the completion offers after --coupling and --model.
    app.add_option("--complete-names", complete_names,
                   "print the bundled coupling or model names, one a line")
        ->check(CLI::IsMember({"couplings", "models"}))
        ->group("");
    app.formatter_fn([](const CLI::App*, std::string, CLI::AppFormatMode) { return overview(); });
    for (const Subcommand* subcommand : subcommands()) {
      Flags* parsed = flags.emplace_back(std::make_unique<Flags>(subcommand->flags())).get();
      CLI::App* sub = app.add_subcommand(std::string(subcommand->name),
                                         std::string(subcommand->summary));
      sub->allow_extras();
      sub->formatter_fn([subcommand, parsed](const CLI::App*, std::string, CLI::AppFormatMode) {
        return usage_text(subcommand->name, subcommand->summary, parsed->specs());
      });
      parsed->add_to(*sub);
    }
  }

  // The subcommand parsed, or -1.
  int chosen() const {
    for (std::size_t k = 0; k < subcommands().size(); ++k) {
      if (app.got_subcommand(std::string(subcommands()[k]->name))) return static_cast<int>(k);
    }
    return -1;
  }
};

int main(int argc, char** argv) {
  const std::span<const char* const> args(argv, static_cast<std::size_t>(argc));
  if (args.size() < 2) {
    fmt::print(stderr, "{}", overview());
    return kBadInput;
  }
  if (!std::string_view(args[1]).starts_with("-") && !is_subcommand(args[1])) {
    fmt::print(stderr, "gearcoupling: error: unknown subcommand '{}' (one of {}; see --help)\n",
               args[1], subcommand_names());
    return kBadInput;
  }
  CommandLine command_line;
  try {
    command_line.app.parse(argc, argv);
  } catch (const CLI::Success& done) {  // --help, --version
    return command_line.app.exit(done);
  } catch (const CLI::ParseError& error) {
    const int k = command_line.chosen();
    fmt::print(stderr, "gearcoupling{}{}: error: {}\n", k < 0 ? "" : " ",
               k < 0 ? "" : subcommands()[k]->name, parse_error_text(error.what()));
    return kBadInput;
  }
  if (command_line.print_completion) {
    fmt::print("{}", bash_completion(subcommands()));
    return 0;
  }
  if (!command_line.complete_names.empty()) {
    try {
      if (command_line.complete_names == "models") {
        for (const std::string& name : bundled_model_names()) fmt::print("{}\n", name);
      } else {
        for (const auto& [name, geometry] : codec::load_coupling_catalog(codec::default_catalog_dir())) {
          fmt::print("{}\n", name);
        }
      }
    } catch (const std::exception& error) {   // a catalogue that does not load: no names
      fmt::print(stderr, "gearcoupling: {}\n", error.what());
      return 1;
    }
    return 0;
  }
  const int k = command_line.chosen();
  if (k < 0) {
    fmt::print(stderr, "{}", overview());
    return kBadInput;
  }
  const Subcommand& subcommand = *subcommands()[k];
  const auto remaining = command_line.app.get_subcommand(std::string(subcommand.name))->remaining();
  if (!remaining.empty()) {
    fmt::print(stderr, "gearcoupling {}: error: {}\n", subcommand.name, unexpected_arguments(remaining));
    return kBadInput;
  }
  return run(subcommand, *command_line.flags[k]);
}

}  // namespace
}  // namespace gc::cli

int main(int argc, char** argv) { return gc::cli::main(argc, argv); }
