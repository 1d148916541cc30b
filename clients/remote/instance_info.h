// A service instance as its status sample describes it (gearcoupling/status, docs/protocol.md):
// the client library's view, also what `gearcoupling status`, the dashboard and /metrics show.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/coupling_definition.h"
#include "gearcoupling.h"

namespace gc::client {

/// One calculation's figures in an instance's status.
struct CalculationStatus {
  std::string calculation;          ///< "tooth_contact", ...
  std::uint64_t served = 0;         ///< OK replies
  std::uint64_t failed = 0;         ///< error replies
  double p50_service_time_s = 0.0;  ///< over its last 4096 requests [s]
  double p99_service_time_s = 0.0;
};

/// One catalogue coupling as the status announces it.
struct CatalogueCoupling {
  std::string name;
  int teeth = 0;               ///< N
  double jam_angle_rad = 0.0;  ///< xi of eq 35 [rad]
  double facewidth_m = 0.0;    ///< F [m]
};

/// A service instance as its latest status describes it.
struct InstanceInfo {
  std::uint64_t id = 0;
  std::string host;
  int pid = 0;
  bool accepting = false;
  unsigned threads = 0;
  double uptime_s = 0.0;
  std::vector<std::string> catalogue;  ///< coupling names it serves
  /// Their definitions, as the instance announced them (the same order; one that does not pass
  /// the protocol's checks is left out).
  std::vector<CouplingDefinition> definitions;
  std::vector<CalculationStatus> calculations;
  std::vector<CatalogueCoupling> couplings;  ///< the catalogue's entries, in its order
};

/// The InstanceInfo a status sample carries. Catalogue definitions the protocol refuses (a name
/// over its bound) are left out of `definitions`, but their names stay in `catalogue`.
InstanceInfo instance_info_from_wire(const gearcoupling_ServiceStatus& status);

}  // namespace gc::client
