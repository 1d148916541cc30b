// The value types of the client's API (client/client.h): its options, what it knows of
// the service instances, what happened to its requests, and a call's outcome. No Cyclone types.
#pragma once

#include <chrono>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "core/coupling_definition.h"

namespace gc::client {

struct ClientOptions {
  int domain = 0;  ///< DDS domain id [0, 230] (protocol/domain_id.h); the network comes from CYCLONEDDS_URI
  /// Longest a call waits, from the call to its reply, including discovery of a service.
  std::chrono::milliseconds timeout{5000};
  /// With DDS Security: the client_id_prefix of this participant's identity (8 hex digits,
  /// written by deploy/security/make-security.sh next to its certificate). Its permissions allow
  /// reading replies only for client ids whose top 32 bits are this prefix. 0: no security, all
  /// 64 bits at random.
  std::uint32_t client_id_prefix = 0;
  /// Longest call() spins on its reply before it sleeps, [0, kMaxSpinBeforeSleep]. 0 (the
  /// default): it sleeps at once, and on a busy host the reply wakes it ahead of CPU hogs. A
  /// control loop that can spare a core for the round trip sets about its deadline: where idle
  /// cores halt (virtual machines), waking a sleeping caller costs more than the round trip's
  /// own work (docs/architecture.md, "Where a control loop's tail comes from").
  std::chrono::microseconds spin_before_sleep{0};
};

/// The bound of ClientOptions::spin_before_sleep: a longer spin is a busy loop, not a wait.
inline constexpr std::chrono::microseconds kMaxSpinBeforeSleep{10000};

/// One calculation's figures in an instance's status.
struct CalculationStatus {
  std::string calculation;          ///< "tooth_contact", ...
  std::uint64_t served = 0;         ///< OK replies
  std::uint64_t failed = 0;         ///< the service's failures (not converged, model or
                                    ///< internal error, deadline exceeded)
  double p50_service_time_s = 0.0;  ///< over its last 4096 requests [s]; 0 before any
  double p99_service_time_s = 0.0;
  std::uint64_t refused = 0;        ///< the client's input refused (invalid, unknown coupling)
  double service_time_sum_s = 0.0;  ///< every request's since the instance started [s]
  /// Whether it was ever called: its quantiles mean nothing before.
  bool called() const { return served + failed + refused > 0; }
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

/// What a call_then callback receives: the result, or the error call() would throw.
template <typename Result>
struct Outcome {
  std::optional<Result> result;  ///< set on success
  std::exception_ptr error;      ///< set on failure
  /// The result, or rethrows the error.
  const Result& value() const {
    if (error) std::rethrow_exception(error);
    return *result;
  }
};

/// What happened to this client's requests so far.
struct ClientCounters {
  std::uint64_t sent = 0;          ///< requests written, resends included
  std::uint64_t replies = 0;       ///< replies matched to a pending request
  std::uint64_t resent = 0;        ///< requests sent again after their instance disappeared
  std::uint64_t duplicates = 0;    ///< replies for a request no longer pending (dropped)
  std::uint64_t foreign = 0;       ///< replies carrying another client's id (never expected)
  std::uint64_t timeouts = 0;      ///< requests failed with Timeout
  std::uint64_t deferred = 0;      ///< writes handed to the client's thread (full window or
                                   ///< 256 in flight), each time
};

}  // namespace gc::client
