// Who asked, and does a reply writer reach them: the check that binds a request's client_id to
// the participant that wrote the request (docs/security.md, docs/protocol.md "The service
// side"). Both answers are cached: the DDS calls behind them copy an endpoint's whole QoS (3 and
// 4 us a request on this machine, on a round trip of about 30 us). Thread-safe.
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <vector>

namespace gc::service {

class Requesters {
 public:
  /// The participant of `publication`, a writer matched with `reader` (a request sample's
  /// publication_handle); nullopt when it is no longer matched.
  std::optional<dds_guid_t> participant_of(dds_entity_t reader, dds_instance_handle_t publication);

  /// True when `writer` has matched a reader belonging to `participant`.
  bool reaches(dds_entity_t writer, const dds_guid_t& participant);

 private:
  /// A writer's matched readers' participants, valid while its matched counts stay the same.
  struct Readers {
    std::uint32_t total = 0;    ///< dds_publication_matched_status_t::total_count
    std::uint32_t current = 0;  ///< ... current_count
    std::vector<dds_guid_t> participants;
  };
  /// Entries are keyed by instance handles, which Cyclone never reuses, so an entry is never
  /// wrong, only unused once its endpoint is gone; the maps are emptied at this size instead of
  /// tracking every endpoint's departure.
  static constexpr std::size_t kMaxEntries = 4096;

  std::mutex mutex_;
  std::unordered_map<dds_instance_handle_t, dds_guid_t> publications_;
  std::unordered_map<dds_instance_handle_t, Readers> writers_;
};

}  // namespace gc::service
