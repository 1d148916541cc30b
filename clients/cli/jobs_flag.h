// -j/--jobs N: the thread count of every subcommand that takes one (batch, validate, diagnose);
// --threads, its spelling before 0.1, is kept as an alias.
#pragma once

#include "clients/cli/command_line.h"

namespace gc::cli {

/// -j, --jobs N (alias --threads), default one per core.
FlagSpec jobs_flag();

/// --jobs in [1, 256]; UsageError naming the flag, value and range otherwise.
int jobs_from(const Flags& flags);

}  // namespace gc::cli
