// The live test-cell topics and the partition they live in, created the same way by every
// process that uses them (monitor, replay, record, dashboard, benchmarks).
#pragma once

#include <dds/dds.h>

#include "protocol/dds_entity.h"

namespace gc::live {

/// A participant on DDS domain `domain` (the network from CYCLONEDDS_URI).
protocol::Entity make_participant(int domain);

protocol::Entity make_measurement_topic(dds_entity_t participant);
protocol::Entity make_residual_topic(dds_entity_t participant);
protocol::Entity make_health_topic(dds_entity_t participant);
protocol::Entity make_model_topic(dds_entity_t participant);

/// A publisher / subscriber in the partition "gearcoupling.live".
protocol::Entity make_live_publisher(dds_entity_t participant);
protocol::Entity make_live_subscriber(dds_entity_t participant);

}  // namespace gc::live
