// The DDS domain ids every gearcoupling program accepts: [0, kMaxDomainId]. No Cyclone types.
#pragma once

namespace gc::protocol {

/// Cyclone maps domain d to UDP ports 7400 + 250 d + ..., the highest a participant uses being
/// 7400 + 250 d + 11 + 2 i for participant index i. With the loopback configuration's up to 120
/// participants per host (deploy/cyclonedds-loopback.xml) that stays below 65536 up to d = 231;
/// 230 is the bound the configuration files and docs/security.md state.
inline constexpr int kMaxDomainId = 230;

}  // namespace gc::protocol
