#include "protocol/matching.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace gc::protocol {

std::uint32_t matched_reader_count(dds_entity_t writer) {
  dds_publication_matched_status_t status{};
  if (dds_get_publication_matched_status(writer, &status) < 0) return 0;
  return status.current_count;
}

bool matched_with_tagged_writer(dds_entity_t reader, const std::string& tag) {
  std::vector<dds_instance_handle_t> handles(64);
  const dds_return_t n = dds_get_matched_publications(reader, handles.data(), handles.size());
  if (n <= 0) return false;
  handles.resize(std::min<std::size_t>(static_cast<std::size_t>(n), handles.size()));
  for (dds_instance_handle_t handle : handles) {
    dds_builtintopic_endpoint_t* endpoint = dds_get_matched_publication_data(reader, handle);
    if (endpoint == nullptr) continue;
    void* value = nullptr;
    size_t size = 0;
    bool same = false;
    if (endpoint->qos != nullptr && dds_qget_userdata(endpoint->qos, &value, &size)) {
      same = size == tag.size() && value != nullptr && tag.compare(0, size, static_cast<const char*>(value), size) == 0;
      dds_free(value);
    }
    dds_builtintopic_free_endpoint(endpoint);
    if (same) return true;
  }
  return false;
}

bool matched_with_reader_of(dds_entity_t writer, const dds_guid_t& participant) {
  std::vector<dds_instance_handle_t> handles(64);
  const dds_return_t n = dds_get_matched_subscriptions(writer, handles.data(), handles.size());
  if (n <= 0) return false;
  handles.resize(std::min<std::size_t>(static_cast<std::size_t>(n), handles.size()));
  for (dds_instance_handle_t handle : handles) {
    dds_builtintopic_endpoint_t* endpoint = dds_get_matched_subscription_data(writer, handle);
    if (endpoint == nullptr) continue;
    const bool same = std::memcmp(endpoint->participant_key.v, participant.v, sizeof(participant.v)) == 0;
    dds_builtintopic_free_endpoint(endpoint);
    if (same) return true;
  }
  return false;
}

std::optional<dds_guid_t> participant_of_publication(dds_entity_t reader,
                                                     dds_instance_handle_t publication) {
  dds_builtintopic_endpoint_t* endpoint = dds_get_matched_publication_data(reader, publication);
  if (endpoint == nullptr) return std::nullopt;
  const dds_guid_t participant = endpoint->participant_key;
  dds_builtintopic_free_endpoint(endpoint);
  return participant;
}

}  // namespace gc::protocol
