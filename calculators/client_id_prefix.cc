#include "calculators/client_id_prefix.h"

#include <charconv>
#include <cstdlib>

#include <stdexcept>

namespace gc::calculators {

std::string client_id_prefix_from_environment() {
  const char* value = std::getenv(kClientIdPrefixEnv);
  return value != nullptr ? value : "";
}

std::uint32_t parse_client_id_prefix(const std::string& text) {
  if (text.empty()) return 0;
  std::uint32_t prefix = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), prefix, 16);
  if (text.size() != 8 || error != std::errc() || end != text.data() + text.size() || prefix == 0) {
    throw std::invalid_argument("--client-id-prefix \"" + text +
                     "\": allowed 8 hexadecimal digits other than 00000000 (the identity's "
                     "client_id_prefix file, docs/security.md)");
  }
  return prefix;
}

}  // namespace gc::calculators
