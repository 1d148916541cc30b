#include "clients/cli/bash_completion.h"

#include <fmt/format.h>

namespace gc::cli {
namespace {

// A flag whose value names a file or a directory: complete paths after it.
bool takes_path(const FlagSpec& spec) {
  return spec.value_name.find("FILE") != std::string::npos ||
         spec.value_name.find("DIR") != std::string::npos;
}

// The case arm of one subcommand: its flags, and those taking a path (space-delimited).
std::string case_arm(const Subcommand& subcommand) {
  std::string flags;
  std::string paths = " ";
  for (const FlagSpec& spec : subcommand.flags()) {
    if (!spec.refused.empty()) continue;
    std::vector<std::string> names = {"--" + spec.name};  // not the aliases: older spellings
    if (spec.short_name != '\0') names.push_back(fmt::format("-{}", spec.short_name));
    for (const std::string& name : names) {
      flags += name + " ";
      if (takes_path(spec)) paths += name + " ";
    }
  }
  return fmt::format("    {}) flags=\"{}--help\"; paths=\"{}\" ;;\n", subcommand.name, flags,
                     paths);
}

}  // namespace

std::string bash_completion(std::span<const Subcommand* const> subcommands) {
  std::string names;
  std::string arms;
  for (const Subcommand* subcommand : subcommands) {
    names += std::string(subcommand->name) + " ";
    arms += case_arm(*subcommand);
  }
  return fmt::format(R"(# bash completion for gearcoupling; written by `gearcoupling --bash-completion`
# from the flag tables of its subcommands.
_gearcoupling() {{
  local cur="${{COMP_WORDS[COMP_CWORD]}}" prev="${{COMP_WORDS[COMP_CWORD-1]}}"
  if (( COMP_CWORD == 1 )); then
    COMPREPLY=($(compgen -W "{}--help --version --bash-completion" -- "$cur"))
    return
  fi
  local flags="" paths=" "
  case "${{COMP_WORDS[1]}}" in
{}  esac
  if [[ "$paths" == *" $prev "* ]]; then
    COMPREPLY=($(compgen -f -- "$cur"))
    return
  fi
  COMPREPLY=($(compgen -W "$flags" -- "$cur"))
}}
complete -o filenames -F _gearcoupling gearcoupling
)",
                     names, arms);
}

}  // namespace gc::cli
