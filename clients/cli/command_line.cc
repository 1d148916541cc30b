#include "clients/cli/command_line.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "analysis/number_text.h"

namespace gc::cli {

using analysis::parse_double;
using analysis::parse_int;
namespace {

// "-j,--jobs,--threads": the names CLI11 matches.
std::string cli11_names(const FlagSpec& spec) {
  std::string names = spec.short_name != '\0' ? fmt::format("-{},", spec.short_name) : "";
  names += "--" + spec.name;
  for (const std::string& alias : spec.aliases) names += ",--" + alias;
  return names;
}

}  // namespace

Flags::Flags(std::vector<FlagSpec> specs) : specs_(std::move(specs)), values_(specs_.size()) {}

void Flags::add_to(CLI::App& app) {
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    const FlagSpec& spec = specs_[k];
    if (spec.is_switch) {
      app.add_flag_function(cli11_names(spec), [this, k](std::int64_t count) {
        if (count > 0) values_[k] = "true";
      }, spec.help)->group(spec.refused.empty() ? "flags" : "")->disable_flag_override();
    } else if (!spec.refused.empty()) {  // its value is taken so check() can name the flag
      app.add_option_function<std::string>(
             cli11_names(spec), [this, k](const std::string& value) { values_[k] = value; })
          ->group("");
    } else {
      app.add_option_function<std::string>(
          cli11_names(spec), [this, k](const std::string& value) { values_[k] = value; },
          spec.help)
          ->type_name(spec.value_name);
    }
  }
}

void Flags::check() const {
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    const FlagSpec& spec = specs_[k];
    if (!spec.refused.empty() && values_[k]) {
      throw UsageError(fmt::format("--{}: {}", spec.name, spec.refused));
    }
    if (!values_[k] && !spec.is_switch && !spec.default_value && spec.refused.empty()) {
      throw UsageError(fmt::format("--{} is required ({})", spec.name, spec.help));
    }
  }
}

std::size_t Flags::index(std::string_view name) const {
  for (std::size_t k = 0; k < specs_.size(); ++k) {
    if (specs_[k].name == name) return k;
  }
  throw UsageError(fmt::format("unknown flag --{} (see --help)", name));
}

const FlagSpec& Flags::spec(std::string_view name) const { return specs_[index(name)]; }

bool Flags::has(std::string_view name) const {
  for (const FlagSpec& spec : specs_) {
    if (spec.name == name && spec.refused.empty()) return true;
  }
  return false;
}

bool Flags::enabled(std::string_view name) const { return has(name) && given(name); }

bool Flags::given(std::string_view name) const { return values_[index(name)].has_value(); }

const std::string& Flags::text(std::string_view name) const {
  const std::size_t k = index(name);
  if (values_[k]) return *values_[k];
  if (!specs_[k].default_value) throw UsageError(fmt::format("--{} is required", name));
  return *specs_[k].default_value;
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

bool parse_flags(Flags& flags, std::span<const char* const> args) {
  CLI::App app;
  app.allow_extras();
  flags.add_to(app);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 pops from the back
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    return false;
  } catch (const CLI::ParseError& error) {
    throw UsageError(parse_error_text(error.what()));
  }
  if (!app.remaining().empty()) throw UsageError(unexpected_arguments(app.remaining()));
  flags.check();
  return true;
}

std::string parse_error_text(std::string_view cli11_message) {
  constexpr std::string_view kRepeated = ": At Most 1 required but received ";
  const std::size_t at = cli11_message.find(kRepeated);
  if (at == std::string_view::npos) return std::string(cli11_message);
  return fmt::format("{} given {} times (at most once)", cli11_message.substr(0, at),
                     cli11_message.substr(at + kRepeated.size()));
}

std::string unexpected_arguments(const std::vector<std::string>& remaining) {
  const std::string& first = remaining.front();
  return first.starts_with("-") ? fmt::format("unknown flag {} (see --help)", first)
                                : fmt::format("unexpected argument '{}'", first);
}

std::string usage_text(std::string_view subcommand, std::string_view summary,
                       const std::vector<FlagSpec>& specs) {
  std::string text = fmt::format("usage: gearcoupling {} [flags]\n\n{}\n\nflags:\n", subcommand,
                                 summary);
  for (const FlagSpec& spec : specs) {
    if (!spec.refused.empty()) continue;
    std::string left =
        spec.is_switch ? "--" + spec.name : fmt::format("--{} <{}>", spec.name, spec.value_name);
    if (spec.short_name != '\0') left = fmt::format("-{}, {}", spec.short_name, left);
    std::string right = spec.help;
    if (spec.default_value) {
      right += fmt::format(" (default {})", spec.default_value->empty() ? "none" : *spec.default_value);
    } else if (!spec.is_switch) {
      right += " (required)";
    }
    for (const std::string& alias : spec.aliases) right += fmt::format("; alias --{}", alias);
    text += fmt::format("  {:<30} {}\n", left, right);
  }
  text += fmt::format("  {:<30} {}\n", "-h, --help", "this text");
  return text;
}

}  // namespace gc::cli
