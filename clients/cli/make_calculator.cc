#include "clients/cli/make_calculator.h"

#include <string>

#include "clients/cli/client_id_prefix_flag.h"
#include "clients/cli/in_process_calculator.h"
#if GC_CLI_REMOTE
#include "clients/cli/remote_calculator.h"
#include "clients/cli/subcommand.h"
#endif

namespace gc::cli {

std::unique_ptr<Calculator> make_calculator(const Flags& flags) {
  if (!flags.enabled("remote")) return std::make_unique<InProcessCalculator>(flags.text("catalogue"));
#if GC_CLI_REMOTE
  client::ClientOptions options;
  options.domain = domain_from(flags);
  const double timeout_s = flags.number("timeout-s");
  if (!(timeout_s > 0.0 && timeout_s <= 3600.0)) {
    throw UsageError("--timeout-s " + flags.text("timeout-s") + ": seconds in (0, 3600]");
  }
  options.timeout = std::chrono::milliseconds(static_cast<long>(timeout_s * 1000.0));
  options.client_id_prefix = parse_client_id_prefix(flags.text("client-id-prefix"));
  return std::make_unique<RemoteCalculator>(options);
#else
  throw UsageError("--remote: this gearcoupling was built without the service (GC_BUILD_SERVICE)");
#endif
}

}  // namespace gc::cli
