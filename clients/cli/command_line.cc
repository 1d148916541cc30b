#include "clients/cli/command_line.h"

#include <fmt/format.h>

#include "analysis/number_text.h"

namespace gc::cli {

using analysis::parse_double;
using analysis::parse_int;

Flags::Flags(std::vector<FlagSpec> specs, std::span<const char* const> args)
    : specs_(std::move(specs)), values_(specs_.size()) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string_view arg = args[i];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
      continue;
    }
    std::optional<std::string> inline_value;
    if (arg.size() >= 2 && arg[0] == '-' && arg[1] != '-') {  // "-j 2" or "-j2"
      if (arg.size() > 2) inline_value = std::string(arg.substr(2));
      arg = long_name(arg[1]);
    } else if (arg.starts_with("--")) {
      arg.remove_prefix(2);
    } else {
      throw UsageError(fmt::format("unexpected argument '{}'", arg));
    }
    if (const auto equals = arg.find('='); equals != std::string_view::npos) {
      inline_value = std::string(arg.substr(equals + 1));
      arg = arg.substr(0, equals);
    }
    const std::size_t k = index(arg);
    if (values_[k]) throw UsageError(fmt::format("--{} given twice", arg));
    if (specs_[k].is_switch) {
      if (inline_value) throw UsageError(fmt::format("--{} takes no value", arg));
      values_[k] = "true";
    } else if (inline_value) {
      values_[k] = std::move(inline_value);
    } else if (i + 1 < args.size()) {
      values_[k] = args[++i];
    } else {
      throw UsageError(fmt::format("--{} needs a value ({})", arg, specs_[k].value_name));
    }
  }
  if (help_) return;
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    if (!values_[k] && !specs_[k].is_switch && !specs_[k].default_value) {
      throw UsageError(fmt::format("--{} is required ({})", specs_[k].name, specs_[k].help));
    }
  }
}

std::string_view Flags::long_name(char short_name) const {
  for (const FlagSpec& spec : specs_) {
    if (spec.short_name == short_name) return spec.name;
  }
  throw UsageError(fmt::format("unknown flag -{} (see --help)", short_name));
}

std::size_t Flags::index(std::string_view name) const {
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    if (specs_[k].name == name) return k;
  }
  throw UsageError(fmt::format("unknown flag --{} (see --help)", name));
}

const FlagSpec& Flags::spec(std::string_view name) const { return specs_[index(name)]; }

bool Flags::enabled(std::string_view name) const { return values_[index(name)].has_value(); }

const std::string& Flags::text(std::string_view name) const {
  const std::size_t k = index(name);
  if (values_[k]) return *values_[k];
  return *specs_[k].default_value;  // present: the constructor checked required flags
}

double Flags::number(std::string_view name) const {
  const std::string& value = text(name);
  const auto parsed = parse_double(value);
  if (!parsed) {
    throw UsageError(fmt::format("--{} '{}' is not a number ({})", name, value, spec(name).help));
  }
  return *parsed;
}

int Flags::integer(std::string_view name, int lo, int hi) const {
  const std::string& value = text(name);
  const auto parsed = parse_int(value);
  if (!parsed) {
    throw UsageError(
        fmt::format("--{} '{}' is not a whole number ({})", name, value, spec(name).help));
  }
  if (*parsed < lo || *parsed > hi) {
    throw UsageError(fmt::format("--{} {} is out of range: allowed a whole number in [{}, {}]",
                                 name, value, lo, hi));
  }
  return *parsed;
}

std::string usage_text(std::string_view subcommand, std::string_view summary,
                       const std::vector<FlagSpec>& specs) {
  std::string text = fmt::format("usage: gearcoupling {} [flags]\n\n{}\n\nflags:\n", subcommand,
                                 summary);
  for (const FlagSpec& spec : specs) {
    std::string left =
        spec.is_switch ? "--" + spec.name : fmt::format("--{} <{}>", spec.name, spec.value_name);
    if (spec.short_name != '\0') left = fmt::format("-{}, {}", spec.short_name, left);
    std::string right = spec.help;
    if (spec.default_value) {
      right += fmt::format(" (default {})", *spec.default_value);
    } else if (!spec.is_switch) {
      right += " (required)";
    }
    text += fmt::format("  {:<28} {}\n", left, right);
  }
  text += fmt::format("  {:<28} {}\n", "--help", "this text");
  return text;
}

}  // namespace gc::cli
