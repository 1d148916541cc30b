#include "clients/cli/make_calculator.h"

#include <charconv>
#include <cstdint>
#include <string>

#include "clients/cli/in_process_calculator.h"
#if GC_CLI_REMOTE
#include "clients/cli/remote_calculator.h"
#include "clients/cli/subcommand.h"
#endif

namespace gc::cli {

#if GC_CLI_REMOTE
namespace {

/// --client-id-prefix: "" (no security) or the 8 hex digits of an identity's client_id_prefix.
std::uint32_t client_id_prefix(const std::string& text) {
  if (text.empty()) return 0;
  std::uint32_t prefix = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), prefix, 16);
  if (text.size() != 8 || error != std::errc() || end != text.data() + text.size() || prefix == 0) {
    throw UsageError("--client-id-prefix \"" + text +
                     "\": allowed 8 hexadecimal digits other than 00000000 (the identity's "
                     "client_id_prefix file, docs/security.md)");
  }
  return prefix;
}

}  // namespace
#endif

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
  options.client_id_prefix = client_id_prefix(flags.text("client-id-prefix"));
  return std::make_unique<RemoteCalculator>(options);
#else
  throw UsageError("--remote: this gearcoupling was built without the service (GC_BUILD_SERVICE)");
#endif
}

}  // namespace gc::cli
