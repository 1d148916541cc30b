#include "clients/cli/make_calculator.h"

#include "clients/cli/in_process_calculator.h"
#if GC_CLI_REMOTE
#include "clients/cli/remote_calculator.h"
#endif

namespace gc::cli {

std::unique_ptr<Calculator> make_calculator(const Flags& flags) {
  if (!flags.enabled("remote")) return std::make_unique<InProcessCalculator>(flags.text("catalog"));
#if GC_CLI_REMOTE
  client::ClientOptions options;
  options.domain = flags.integer("domain", 0, 232);
  const double timeout_s = flags.number("timeout");
  if (!(timeout_s > 0.0 && timeout_s <= 3600.0)) {
    throw UsageError("--timeout " + flags.text("timeout") + ": seconds in (0, 3600]");
  }
  options.timeout = std::chrono::milliseconds(static_cast<long>(timeout_s * 1000.0));
  return std::make_unique<RemoteCalculator>(options);
#else
  throw UsageError("--remote: this gearcoupling was built without the service (GC_BUILD_SERVICE)");
#endif
}

}  // namespace gc::cli
