// The Calculator the common flags ask for (calculators/make_calculator.h): in process, or
// gearcoupling-service with --remote.
#pragma once

#include <memory>

#include "calculators/calculator.h"
#include "clients/cli/command_line.h"

namespace gc::cli {

/// --remote [--domain N] [--timeout-s S] [--client-id-prefix HEX8]: a RemoteCalculator whose
/// --timeout-s is the deadline of the whole command, from now (every request of the command,
/// discovery included, is answered by then or fails with client::Timeout); otherwise an
/// InProcessCalculator on --catalogue. Throws UsageError for a bad flag, or for --remote in a
/// build without the service.
std::unique_ptr<calculators::Calculator> make_calculator(const Flags& flags);

}  // namespace gc::cli
