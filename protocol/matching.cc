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

namespace {

/// True when `test` holds for one of the endpoints matched with `entity`: `handles_of` lists them
/// (dds_get_matched_publications or _subscriptions), `data_of` reads one (freed here).
template <typename Handles, typename Data, typename Test>
bool any_matched(dds_entity_t entity, Handles handles_of, Data data_of, Test test) {
  std::vector<dds_instance_handle_t> handles(64);
  const dds_return_t n = handles_of(entity, handles.data(), handles.size());
  if (n <= 0) return false;
  handles.resize(std::min<std::size_t>(static_cast<std::size_t>(n), handles.size()));
  for (dds_instance_handle_t handle : handles) {
    dds_builtintopic_endpoint_t* endpoint = data_of(entity, handle);
    if (endpoint == nullptr) continue;
    const bool found = test(*endpoint);
    dds_builtintopic_free_endpoint(endpoint);
    if (found) return true;
  }
  return false;
}

}  // namespace

bool matched_with_tagged_writer(dds_entity_t reader, const std::string& tag) {
  return any_matched(reader, dds_get_matched_publications, dds_get_matched_publication_data,
                     [&tag](const dds_builtintopic_endpoint_t& endpoint) {
                       void* value = nullptr;
                       size_t size = 0;
                       bool same = false;
                       if (endpoint.qos != nullptr && dds_qget_userdata(endpoint.qos, &value, &size)) {
                         same = size == tag.size() && value != nullptr &&
                                tag.compare(0, size, static_cast<const char*>(value), size) == 0;
                         dds_free(value);
                       }
                       return same;
                     });
}

bool matched_with_reader_of(dds_entity_t writer, const dds_guid_t& participant) {
  return any_matched(writer, dds_get_matched_subscriptions, dds_get_matched_subscription_data,
                     [&participant](const dds_builtintopic_endpoint_t& endpoint) {
                       return std::memcmp(endpoint.participant_key.v, participant.v, sizeof(participant.v)) == 0;
                     });
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
