// The bash completion of gearcoupling, written from the subcommands' flag tables (FlagSpec), so
// it completes exactly what the parser accepts. Installed to
// share/bash-completion/completions/gearcoupling; `gearcoupling --bash-completion` prints it.
#pragma once

#include <span>
#include <string>

#include "clients/cli/subcommand.h"

namespace gc::cli {

/// A bash script defining _gearcoupling and `complete -F _gearcoupling gearcoupling`:
/// subcommand names after the program, a subcommand's flags after it (not their aliases), file names after a flag
/// whose value is a FILE or DIR, and after --coupling and --model also the bundled names
/// (`gearcoupling --complete-names couplings|models`, asked at completion time).
std::string bash_completion(std::span<const Subcommand* const> subcommands);

}  // namespace gc::cli
