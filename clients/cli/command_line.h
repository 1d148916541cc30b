// Flags of one subcommand, declared as a table (FlagSpec) and parsed by CLI11: "--name value",
// "--name=value", "-j 2", "-j2" or a bare "--switch". The same table gives the help text and the
// bash completion (bash_completion.h); anything not in it is a usage error.
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
}

namespace gc::cli {

/// Bad command line: the message names the flag and what it accepts. Exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FlagSpec {
  std::string name;                        ///< without the leading "--"; ends in its unit
  std::string value_name;                  ///< shown in help, e.g. "N·m"; empty for a switch
  std::string help;
  std::optional<std::string> default_value;  ///< none: the flag is required (unless a switch)
  bool is_switch = false;
  char short_name = '\0';                  ///< e.g. 'j' for "-j N"; '\0' for none
  std::vector<std::string> aliases = {};   ///< older spellings still accepted, without "--"
  /// Not empty: the flag is refused with this reason (a flag other subcommands take that this
  /// one cannot honour); such a flag is left out of the help and the completion.
  std::string refused = {};
};

/// The values of one subcommand's flags. Bound to a CLI::App by add_to(), so it stays where it
/// was made (neither copied nor moved).
class Flags {
 public:
  explicit Flags(std::vector<FlagSpec> specs);
  Flags(const Flags&) = delete;
  Flags& operator=(const Flags&) = delete;

  /// Declares every flag on `app` (a subcommand): parsing `app` fills this object.
  void add_to(CLI::App& app);
  /// After parsing: UsageError for a refused flag given, or a required flag absent.
  void check() const;

  bool has(std::string_view name) const;              ///< this subcommand declares the flag
  bool enabled(std::string_view name) const;          ///< a switch
  bool given(std::string_view name) const;            ///< on the command line, not defaulted
  const std::string& text(std::string_view name) const;  ///< as given, or the default
  /// The flag as a number; UsageError naming the flag when it is not one.
  double number(std::string_view name) const;
  /// The flag as an int in [lo, hi]; UsageError naming the flag, value and range otherwise.
  int integer(std::string_view name, int lo, int hi) const;
  const std::vector<FlagSpec>& specs() const { return specs_; }

 private:
  const FlagSpec& spec(std::string_view name) const;
  std::size_t index(std::string_view name) const;

  std::vector<FlagSpec> specs_;
  std::vector<std::optional<std::string>> values_;  // parallel to specs_
};

/// Parses `args` (after the subcommand name) into `flags` with a CLI::App of their own; for
/// tests and one-subcommand programs. Returns false when --help was asked for.
bool parse_flags(Flags& flags, std::span<const char* const> args);

/// "unknown flag --x (see --help)" or "unexpected argument 'x'": what CLI11 could not place
/// (CLI::App::remaining()), which must not be empty.
std::string unexpected_arguments(const std::vector<std::string>& remaining);

/// CLI11's message for a parse error in the CLI's words: "--torque-nm given 2 times (at most
/// once)" for its "At Most 1 required but received 2"; other messages as they are.
std::string parse_error_text(std::string_view cli11_message);

/// Help text: usage line, summary, every flag with its unit, aliases, default or "required".
std::string usage_text(std::string_view subcommand, std::string_view summary,
                       const std::vector<FlagSpec>& specs);

}  // namespace gc::cli
