// --client-id-prefix HEX8 (or $GC_CLIENT_ID_PREFIX): under DDS Security, the client_id_prefix of
// the process's client identity (docs/security.md). What a RemoteCalculator's client needs;
// shared by gearcoupling --remote and gearcoupling-dashboard's query panel.
#pragma once

#include <cstdint>
#include <string>

namespace gc::calculators {

/// The environment variable that gives --client-id-prefix its default.
inline constexpr const char* kClientIdPrefixEnv = "GC_CLIENT_ID_PREFIX";

/// What the flag says in --help.
inline constexpr const char* kClientIdPrefixHelp =
    "the client_id_prefix of this identity under DDS Security: the 8 hex digits written next "
    "to its certificate (docs/security.md; $GC_CLIENT_ID_PREFIX)";

/// $GC_CLIENT_ID_PREFIX, or "" when it is not set.
std::string client_id_prefix_from_environment();

/// "" (no security: 0) or 8 hexadecimal digits other than 00000000; std::invalid_argument naming
/// the flag, the value and what is allowed otherwise.
std::uint32_t parse_client_id_prefix(const std::string& text);

}  // namespace gc::calculators
