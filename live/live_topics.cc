#include "live/live_topics.h"

#include <fmt/format.h>

#include <string>
#include <vector>

#include "gearcoupling.h"
#include "live/live_names.h"
#include "live/live_qos.h"
#include "protocol/matching.h"
#include "protocol/qos.h"

namespace gc::live {

using protocol::check_dds;
using protocol::Entity;

namespace {

Entity make_topic(dds_entity_t participant, const dds_topic_descriptor_t& type, const char* name,
                  const protocol::Qos& qos) {
  return Entity(check_dds(dds_create_topic(participant, &type, name, qos.get(), nullptr),
                          "dds_create_topic(live)"));
}

}  // namespace

Entity make_participant(int domain) {
  return Entity(protocol::create_participant(domain, protocol::dds_config()));
}

Entity make_measurement_topic(dds_entity_t participant) {
  return make_topic(participant, gearcoupling_MeasurementBatch_desc, kMeasurementTopic,
                    measurement_reader_qos());
}
Entity make_residual_topic(dds_entity_t participant) {
  return make_topic(participant, gearcoupling_ResidualBatch_desc, kResidualTopic, residual_qos());
}
Entity make_health_topic(dds_entity_t participant) {
  return make_topic(participant, gearcoupling_CellHealth_desc, kHealthTopic, health_reader_qos());
}
Entity make_model_topic(dds_entity_t participant) {
  return make_topic(participant, gearcoupling_ModelSwap_desc, kModelTopic, model_qos());
}

Entity make_proposal_topic(dds_entity_t participant) {
  return make_topic(participant, gearcoupling_ModelProposal_desc, kProposalTopic, proposal_qos());
}
Entity make_monitor_status_topic(dds_entity_t participant) {
  return make_topic(participant, gearcoupling_MonitorStatus_desc, kMonitorTopic,
                    monitor_status_qos());
}

Entity make_live_publisher(dds_entity_t participant) {
  const protocol::Qos partition = protocol::partition_qos(kLivePartition);
  return Entity(check_dds(dds_create_publisher(participant, partition.get(), nullptr),
                          "dds_create_publisher(live)"));
}

Entity make_live_subscriber(dds_entity_t participant) {
  const protocol::Qos partition = protocol::partition_qos(kLivePartition);
  return Entity(check_dds(dds_create_subscriber(participant, partition.get(), nullptr),
                          "dds_create_subscriber(live)"));
}

Entity make_cell_publisher(dds_entity_t participant, const std::string& test_cell) {
  const protocol::Qos partition = protocol::partition_qos(cell_partition(test_cell));
  return Entity(check_dds(dds_create_publisher(participant, partition.get(), nullptr),
                          "dds_create_publisher(live, a test cell's partition)"));
}

namespace {

protocol::Qos partitions_qos(const std::vector<std::string>& partitions) {
  protocol::Qos qos;
  std::vector<const char*> names;
  for (const std::string& p : partitions) names.push_back(p.c_str());
  dds_qset_partition(qos.get(), static_cast<uint32_t>(names.size()), names.data());
  return qos;
}

}  // namespace

Entity make_publisher_in(dds_entity_t participant, const std::vector<std::string>& partitions) {
  return Entity(check_dds(dds_create_publisher(participant, partitions_qos(partitions).get(), nullptr),
                          "dds_create_publisher(live)"));
}

Entity make_subscriber_in(dds_entity_t participant, const std::vector<std::string>& partitions) {
  return Entity(check_dds(dds_create_subscriber(participant, partitions_qos(partitions).get(), nullptr),
                          "dds_create_subscriber(live)"));
}

std::vector<std::string> writer_partitions(dds_entity_t reader, dds_instance_handle_t publication) {
  std::vector<std::string> out;
  dds_builtintopic_endpoint_t* endpoint = dds_get_matched_publication_data(reader, publication);
  if (endpoint == nullptr) return out;
  uint32_t count = 0;
  char** names = nullptr;
  if (endpoint->qos != nullptr && dds_qget_partition(endpoint->qos, &count, &names)) {
    for (uint32_t i = 0; i < count; ++i) {
      out.emplace_back(names[i]);
      dds_free(names[i]);
    }
    dds_free(names);
  }
  dds_builtintopic_free_endpoint(endpoint);
  return out;
}

WriterInfo writer_info(dds_entity_t reader, dds_instance_handle_t publication) {
  WriterInfo out;
  dds_builtintopic_endpoint_t* endpoint = dds_get_matched_publication_data(reader, publication);
  if (endpoint == nullptr) return out;
  void* data = nullptr;
  size_t size = 0;
  if (endpoint->qos != nullptr && dds_qget_userdata(endpoint->qos, &data, &size) && data != nullptr) {
    out.user_data.assign(static_cast<const char*>(data), size);
    dds_free(data);
  }
  for (unsigned char byte : endpoint->participant_key.v) out.participant += fmt::format("{:02x}", byte);
  for (unsigned char byte : endpoint->key.v) out.writer += fmt::format("{:02x}", byte);
  dds_builtintopic_free_endpoint(endpoint);
  return out;
}

bool wait_for_readers(dds_entity_t writer, std::uint32_t readers, std::chrono::milliseconds timeout) {
  return protocol::wait_until([&] { return protocol::matched_reader_count(writer) >= readers; },
                              std::chrono::steady_clock::now() + timeout);
}

}  // namespace gc::live
