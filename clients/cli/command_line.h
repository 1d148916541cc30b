// Flags of one subcommand: "--name value", "--name=value" or a bare "--switch". Each subcommand
// declares its flags; anything else on the command line is a usage error.
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gc::cli {

/// Bad command line: the message names the flag and what it accepts. Exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FlagSpec {
  std::string name;                        ///< without the leading "--"
  std::string value_name;                  ///< shown in help, e.g. "N·m"; empty for a switch
  std::string help;
  std::optional<std::string> default_value;  ///< none: the flag is required (unless a switch)
  bool is_switch = false;
  char short_name = '\0';                  ///< e.g. 'j' for "-j N"; '\0' for none
};

class Flags {
 public:
  /// Parses `args` (after the subcommand name). Throws UsageError for an unknown flag, a missing
  /// value, a flag given twice or a required flag absent. "--help" is always accepted.
  Flags(std::vector<FlagSpec> specs, std::span<const char* const> args);

  bool help_requested() const { return help_; }
  bool enabled(std::string_view name) const;          ///< a switch
  const std::string& text(std::string_view name) const;  ///< as given, or the default
  /// The flag as a number; UsageError naming the flag when it is not one.
  double number(std::string_view name) const;
  /// The flag as an int in [lo, hi]; UsageError naming the flag, value and range otherwise.
  int integer(std::string_view name, int lo, int hi) const;
  const std::vector<FlagSpec>& specs() const { return specs_; }

 private:
  const FlagSpec& spec(std::string_view name) const;
  std::string_view long_name(char short_name) const;
  std::size_t index(std::string_view name) const;

  std::vector<FlagSpec> specs_;
  std::vector<std::optional<std::string>> values_;  // parallel to specs_
  bool help_ = false;
};

/// Help text: usage line, summary, every flag with its unit, default or "required".
std::string usage_text(std::string_view subcommand, std::string_view summary,
                       const std::vector<FlagSpec>& specs);

}  // namespace gc::cli
