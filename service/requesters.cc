#include "service/requesters.h"

#include <algorithm>
#include <cstring>

#include "protocol/matching.h"

namespace gc::service {
namespace {

bool same(const dds_guid_t& a, const dds_guid_t& b) {
  return std::memcmp(a.v, b.v, sizeof(a.v)) == 0;
}

/// The participants of every reader matched with `writer`.
std::vector<dds_guid_t> reader_participants(dds_entity_t writer) {
  std::vector<dds_instance_handle_t> handles(64);
  dds_return_t n = dds_get_matched_subscriptions(writer, handles.data(), handles.size());
  if (n > static_cast<dds_return_t>(handles.size())) {  // more than 64: ask again for all
    handles.resize(static_cast<std::size_t>(n));
    n = dds_get_matched_subscriptions(writer, handles.data(), handles.size());
  }
  std::vector<dds_guid_t> out;
  for (dds_return_t i = 0; i < std::min<dds_return_t>(n, static_cast<dds_return_t>(handles.size())); ++i) {
    dds_builtintopic_endpoint_t* endpoint = dds_get_matched_subscription_data(writer, handles[i]);
    if (endpoint == nullptr) continue;
    out.push_back(endpoint->participant_key);
    dds_builtintopic_free_endpoint(endpoint);
  }
  return out;
}

}  // namespace

std::optional<dds_guid_t> Requesters::participant_of(dds_entity_t reader,
                                                     dds_instance_handle_t publication) {
  {
    std::lock_guard lock(mutex_);
    const auto found = publications_.find(publication);
    if (found != publications_.end()) return found->second;
  }
  const std::optional<dds_guid_t> participant =
      protocol::participant_of_publication(reader, publication);
  if (participant) {
    std::lock_guard lock(mutex_);
    if (publications_.size() >= kMaxEntries) publications_.clear();
    publications_.emplace(publication, *participant);
  }
  return participant;
}

bool Requesters::reaches(dds_entity_t writer, const dds_guid_t& participant) {
  dds_instance_handle_t handle = 0;
  dds_publication_matched_status_t status{};
  if (dds_get_instance_handle(writer, &handle) < 0 ||
      dds_get_publication_matched_status(writer, &status) < 0) {
    return false;
  }
  std::lock_guard lock(mutex_);
  auto found = writers_.find(handle);
  if (found == writers_.end() || found->second.total != status.total_count ||
      found->second.current != status.current_count) {
    // A reader came or went since: ask DDS again. The counts are read before the readers, so a
    // change in between leaves the entry stale (refreshed next time), never older than its counts.
    if (found == writers_.end() && writers_.size() >= kMaxEntries) writers_.clear();
    found = writers_.insert_or_assign(handle, Readers{status.total_count, status.current_count,
                                                      reader_participants(writer)}).first;
  }
  const std::vector<dds_guid_t>& participants = found->second.participants;
  return std::any_of(participants.begin(), participants.end(),
                     [&](const dds_guid_t& p) { return same(p, participant); });
}

}  // namespace gc::service
