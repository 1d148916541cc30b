#include "clients/cli/bash_completion.h"

#include <fmt/format.h>

namespace gc::cli {
namespace {

// A flag whose value names a file or a directory: complete paths after it.
bool takes_path(const FlagSpec& spec) {
  return spec.value_name.find("FILE") != std::string::npos ||
         spec.value_name.find("DIR") != std::string::npos;
}

// A flag whose value may be a bundled name (--coupling NAME|FILE, --model FILE|NAME): the kind
// of `gearcoupling --complete-names KIND` that lists them, "" for any other flag.
std::string names_kind(const FlagSpec& spec) {
  if (spec.value_name.find("NAME") == std::string::npos) return "";
  if (spec.name == "coupling") return "couplings";
  if (spec.name == "model") return "models";
  return "";
}

// The case arm of one subcommand: its flags, those taking a path, and those taking a bundled
// name as FLAG:KIND (space-delimited).
std::string case_arm(const Subcommand& subcommand) {
  std::string flags;
  std::string paths = " ";
  std::string name_flags = " ";
  for (const FlagSpec& spec : subcommand.flags()) {
    if (!spec.refused.empty()) continue;
    std::vector<std::string> names = {"--" + spec.name};  // not the aliases: older spellings
    if (spec.short_name != '\0') names.push_back(fmt::format("-{}", spec.short_name));
    for (const std::string& name : names) {
      flags += name + " ";
      if (takes_path(spec)) paths += name + " ";
      if (!names_kind(spec).empty()) name_flags += name + ":" + names_kind(spec) + " ";
    }
  }
  return fmt::format("    {}) flags=\"{}--help\"; paths=\"{}\"; names=\"{}\" ;;\n", subcommand.name,
                     flags, paths, name_flags);
}

}  // namespace

std::string bash_completion(std::span<const Subcommand* const> subcommands) {
  std::string names;
  std::string arms;
  for (const Subcommand* subcommand : subcommands) {
    names += std::string(subcommand->name) + " ";
    arms += case_arm(*subcommand);
  }
  return fmt::format(R"bash(# bash completion for gearcoupling; written by `gearcoupling --bash-completion`
# from the flag tables of its subcommands.
_gearcoupling() {{
  local cur="${{COMP_WORDS[COMP_CWORD]}}" prev="${{COMP_WORDS[COMP_CWORD-1]}}"
  if (( COMP_CWORD == 1 )); then
    COMPREPLY=($(compgen -W "{}--help --version --bash-completion" -- "$cur"))
    return
  fi
  local flags="" paths=" " names=" " kind
  case "${{COMP_WORDS[1]}}" in
{}  esac
  # A flag that takes a bundled coupling or model name: the names there are (the program lists
  # them, $GEARCOUPLING_CATALOG and $GEARCOUPLING_MODELS honoured), and files.
  if [[ "$names" == *" $prev:"* ]]; then
    kind=${{names#* $prev:}}; kind=${{kind%% *}}
    COMPREPLY=($(compgen -W "$("${{COMP_WORDS[0]}}" --complete-names "$kind" 2>/dev/null)" -- "$cur")
               $(compgen -f -- "$cur"))
    return 0
  fi
  if [[ "$paths" == *" $prev "* ]]; then
    COMPREPLY=($(compgen -f -- "$cur"))
    return
  fi
  COMPREPLY=($(compgen -W "$flags" -- "$cur"))
}}
complete -o filenames -F _gearcoupling gearcoupling
)bash",
                     names, arms);
}

}  // namespace gc::cli
