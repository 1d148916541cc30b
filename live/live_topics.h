// The live test-cell topics and the partition they live in, created the same way by every
// process that uses them (monitor, replay, record, dashboard, benchmarks).
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "protocol/dds_entity.h"

namespace gc::live {

/// A participant on DDS domain `domain` (the network from CYCLONEDDS_URI).
protocol::Entity make_participant(int domain);

protocol::Entity make_measurement_topic(dds_entity_t participant);
protocol::Entity make_residual_topic(dds_entity_t participant);
protocol::Entity make_health_topic(dds_entity_t participant);
protocol::Entity make_model_topic(dds_entity_t participant);
protocol::Entity make_proposal_topic(dds_entity_t participant);
protocol::Entity make_monitor_status_topic(dds_entity_t participant);

/// A publisher / subscriber in the partition "gearcoupling.live".
protocol::Entity make_live_publisher(dds_entity_t participant);
protocol::Entity make_live_subscriber(dds_entity_t participant);
/// A publisher in test cell `test_cell`'s own partition (cell_partition): its measurements and
/// model swaps.
protocol::Entity make_cell_publisher(dds_entity_t participant, const std::string& test_cell);
/// A publisher in `partitions` (a model swap's: its cell's and its operator's).
protocol::Entity make_publisher_in(dds_entity_t participant,
                                   const std::vector<std::string>& partitions);
/// A subscriber in `partitions` (e.g. kLivePartition and kEveryCellPartition).
protocol::Entity make_subscriber_in(dds_entity_t participant,
                                    const std::vector<std::string>& partitions);

/// The partitions of `publication`, a writer matched with `reader` (a sample's
/// publication_handle); empty when it is no longer matched.
std::vector<std::string> writer_partitions(dds_entity_t reader, dds_instance_handle_t publication);

/// What the matched writer `publication` of `reader` says of itself: its USER_DATA as text and
/// its participant's GUID (32 hex digits); empty when it is no longer matched.
struct WriterInfo {
  std::string user_data, participant, writer;   ///< the GUIDs in 32 hex digits
};
WriterInfo writer_info(dds_entity_t reader, dds_instance_handle_t publication);

/// Waits until `writer` has at least `readers` matched readers (a sample written before a
/// reader is matched is lost to it). Returns whether it had them within `timeout`.
bool wait_for_readers(dds_entity_t writer, std::uint32_t readers, std::chrono::milliseconds timeout);

}  // namespace gc::live
