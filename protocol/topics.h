// The protocol's topics on one participant, created the same way by the service and clients.
#pragma once

#include <array>

#include "protocol/calculation.h"
#include "protocol/dds_entity.h"

namespace gc::protocol {

/// The five request topics, indexed by index_of(Calculation).
std::array<Entity, gc::protocol::kCalculationCount> make_request_topics(dds_entity_t participant);
/// The five reply topics, indexed by index_of(Calculation).
std::array<Entity, gc::protocol::kCalculationCount> make_reply_topics(dds_entity_t participant);
/// "gearcoupling/status".
Entity make_status_topic(dds_entity_t participant);

/// The raw handles of `entities`.
std::array<dds_entity_t, gc::protocol::kCalculationCount> handles(const std::array<Entity, gc::protocol::kCalculationCount>& entities);

}  // namespace gc::protocol
