// The status topic of one instance: who it is, where to send requests, what it serves, how it
// is doing (docs/protocol.md). Clients discover instances through it.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "protocol/dds_entity.h"
#include "service/catalogue.h"
#include "service/service_stats.h"

namespace gc::service {

class StatusPublisher {
 public:
  StatusPublisher(dds_entity_t participant, std::uint64_t instance_id, unsigned threads,
                  double liveliness_lease_s, const Catalogue& catalogue,
                  const ServiceStats& stats);
  /// Writes the current status; `accepting` false tells clients to send new requests elsewhere.
  void publish(bool accepting);
  /// Disposes this instance's status: clients drop it at once (graceful shutdown).
  void dispose();

 private:
  std::uint64_t instance_id_;
  unsigned threads_;
  const Catalogue& catalogue_;
  const ServiceStats& stats_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::string host_;
  protocol::Entity topic_;
  protocol::Entity publisher_;
  protocol::Entity writer_;
};

}  // namespace gc::service
