// The Calculator the common flags ask for: in process, or gearcoupling-service with --remote.
#pragma once

#include <memory>

#include "clients/cli/calculator.h"
#include "clients/cli/command_line.h"

namespace gc::cli {

/// --remote [--domain N] [--timeout-s S]: a RemoteCalculator; otherwise an InProcessCalculator
/// on --catalogue. Throws UsageError for --remote in a build without the service.
std::unique_ptr<Calculator> make_calculator(const Flags& flags);

}  // namespace gc::cli
