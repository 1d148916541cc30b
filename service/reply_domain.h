// The Cyclone domain that holds the service's reply writers: a domain of its own in this process,
// which the network sees as the service's domain (Cyclone's Discovery/ExternalDomainId), so a
// client's reply reader matches its writers as any other of the service's.
//
// Why a domain of its own: Cyclone 0.10.2 (Debian 12's) keeps about 0.5-0.7 kB for every reader
// or writer deleted in a domain, until the domain itself is deleted. Its discovery writer's
// history cache takes a reference on the endpoint's key-map entry (ddsi_tkmap_find, keyed by the
// endpoint's GUID, never reused) and, when the endpoint is unregistered, frees its index node
// without releasing it (dds_whc.c; fixed upstream after 0.10.2, "Fix tkmap_instance leak in
// WHC"). Neither the partition, the publisher nor the reply topic's instances matter: a writer
// made and deleted in a loop on one publisher leaks as much as one in a new partition each time.
// The service makes a writer per client (ReplyWriters), so clients that come and go, one a
// second, grew it by 2.5-4 MiB an hour. ReplyWriters makes a new ReplyDomain every so many
// writers and deletes the old one once its writers have moved: what Cyclone keeps goes with it.
#pragma once

#include <array>
#include <cstddef>

#include <dds/dds.h>

#include "protocol/calculation.h"
#include "protocol/dds_config.h"
#include "protocol/dds_entity.h"

namespace gc::service {

class ReplyDomain {
 public:
  /// A new domain, seen on the network as DDS domain `domain`, with configuration `dds` (the
  /// service's own), one participant and the five reply topics. Its local id (the one Cyclone's
  /// access control checks) is the highest of 0-230 not in use in this process and not
  /// `domain`. Throws protocol::DdsError.
  ReplyDomain(int domain, const protocol::DdsConfig& dds);
  /// Deletes the domain with every entity in it (and what Cyclone kept for deleted ones), then
  /// hands the memory freed back to the system (malloc_trim): glibc keeps what a program frees
  /// in the arenas of the threads that used it, and a domain's threads spread it over several.
  ~ReplyDomain();
  ReplyDomain(const ReplyDomain&) = delete;
  ReplyDomain& operator=(const ReplyDomain&) = delete;

  dds_entity_t participant() const { return participant_.get(); }
  /// Calculation `index`'s reply topic (protocol::index_of).
  dds_entity_t reply_topic(std::size_t index) const { return reply_topics_[index].get(); }

 private:
  // Declared first, deleted last: deleting it deletes everything below as well.
  protocol::Entity domain_;
  protocol::Entity participant_;
  std::array<protocol::Entity, gc::protocol::kCalculationCount> reply_topics_;
};

}  // namespace gc::service
