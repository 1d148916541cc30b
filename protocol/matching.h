// Is the other side there yet? Matching checks that close the discovery race of request/reply
// (a sample written before the reader on the other side is matched is lost).
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <thread>

namespace gc::protocol {

/// Readers currently matched with `writer`.
std::uint32_t matched_reader_count(dds_entity_t writer);

/// True when `reader` is matched with at least one writer whose USER_DATA equals `tag`.
bool matched_with_tagged_writer(dds_entity_t reader, const std::string& tag);

/// True when `writer` is matched with a reader of participant `participant` (a GUID's
/// participant key): what Cyclone knows now, before the built-in topics report that reader.
bool matched_with_reader_of(dds_entity_t writer, const dds_guid_t& participant);

/// The participant of `publication`, a writer matched with `reader` (a sample's
/// dds_sample_info_t::publication_handle); nullopt when it is no longer matched.
std::optional<dds_guid_t> participant_of_publication(dds_entity_t reader,
                                                     dds_instance_handle_t publication);

/// Calls `ready` every `poll` until it returns true or `deadline` passes; returns its last value.
template <typename Predicate>
bool wait_until(Predicate ready, std::chrono::steady_clock::time_point deadline,
                std::chrono::microseconds poll = std::chrono::microseconds(500)) {
  while (!ready()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(poll);
  }
  return true;
}

}  // namespace gc::protocol
