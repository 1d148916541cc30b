#include "calculators/make_calculator.h"

#include <stdexcept>

#include "calculators/in_process_calculator.h"
#if GC_CALCULATORS_REMOTE
#include "calculators/remote_calculator.h"
#endif

namespace gc::calculators {

std::unique_ptr<Calculator> make_calculator(const CalculatorSettings& settings) {
  if (!settings.remote) return std::make_unique<InProcessCalculator>(settings.catalog_dir);
#if GC_CALCULATORS_REMOTE
  client::ClientOptions options;
  options.domain = settings.domain;
  options.timeout = settings.timeout;
  options.client_id_prefix = settings.client_id_prefix;
  return std::make_unique<RemoteCalculator>(options, settings.timeout_is_deadline);
#else
  throw std::invalid_argument(
      "--remote: this build has no service client (built without GC_BUILD_SERVICE)");
#endif
}

}  // namespace gc::calculators
