#include "clients/cli/make_calculator.h"

#include <stdexcept>
#include <string>

#include "calculators/client_id_prefix.h"
#include "calculators/make_calculator.h"
#include "clients/cli/subcommand.h"

namespace gc::cli {

std::unique_ptr<calculators::Calculator> make_calculator(const Flags& flags) {
  calculators::CalculatorSettings settings;
  settings.catalog_dir = flags.text("catalogue");
  settings.remote = flags.enabled("remote");
  if (settings.remote) {
    settings.domain = domain_from(flags);
    const double timeout_s = flags.number("timeout-s");
    if (!(timeout_s > 0.0 && timeout_s <= 3600.0)) {
      throw UsageError("--timeout-s " + flags.text("timeout-s") + ": seconds in (0, 3600]");
    }
    settings.timeout = std::chrono::milliseconds(static_cast<long>(timeout_s * 1000.0));
    settings.timeout_is_deadline = true;
  }
  try {
    if (settings.remote) {
      settings.client_id_prefix =
          calculators::parse_client_id_prefix(flags.text("client-id-prefix"));
    }
    return calculators::make_calculator(settings);
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
}

}  // namespace gc::cli
