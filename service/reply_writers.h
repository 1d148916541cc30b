// One reply writer per (client, calculation), each in that client's own reply partition
// ("gearcoupling.reply.<client id>"), so a reply travels only to the client that asked, on the
// wire. Writers are created when discovery reports a client's reply reader (before the client
// may send, see docs/protocol.md) or, for a client that did not wait, at its first request; they
// are deleted when the reader goes. Every writer carries this instance's id as USER_DATA, by
// which a client knows this instance's writer has matched its reader.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "protocol/calculation.h"
#include "protocol/dds_entity.h"

namespace gc::service {

class ReplyWriters {
 public:
  /// `reply_topics[index_of(c)]` is calculation c's reply topic on `participant`.
  /// Writes block at most `max_blocking_s` for an unacknowledging client.
  ReplyWriters(dds_entity_t participant, std::array<dds_entity_t, 5> reply_topics,
               std::string instance_tag, double max_blocking_s);

  /// A reader of `calculation`'s replies appeared in `client_id`'s partition: make its writer.
  void reader_appeared(std::uint64_t client_id, protocol::Calculation calculation);
  /// That reader went (the client left): delete the writer once no reader of it remains.
  void reader_gone(std::uint64_t client_id, protocol::Calculation calculation);

  /// The writer for (client, calculation), created if discovery has not reported the reader
  /// yet, after waiting until `deadline` for a reader to match it. 0 when none matched (the
  /// client is gone or never waited for discovery) or the client has departed (its readers
  /// went): the reply cannot be delivered.
  dds_entity_t matched_writer(std::uint64_t client_id, protocol::Calculation calculation,
                              std::chrono::steady_clock::time_point deadline);

  /// A reply to `client_id` could not be written in time (a killed client whose reader has not
  /// yet expired): drop its further replies at once, for `hold_s` or until one of its readers
  /// appears again, instead of blocking a worker on each.
  void mark_departed(std::uint64_t client_id, double hold_s);

  /// Clients with at least one writer.
  std::size_t clients() const;

 private:
  struct Writer {
    protocol::Entity publisher;
    protocol::Entity writer;
    int readers = 0;  ///< discovered readers of this (client, calculation)
  };
  using Key = std::pair<std::uint64_t, int>;

  dds_entity_t writer_locked(const Key& key);

  dds_entity_t participant_;
  std::array<dds_entity_t, 5> reply_topics_;
  std::string instance_tag_;
  double max_blocking_s_;
  mutable std::mutex mutex_;
  std::map<Key, Writer> writers_;
  /// Clients whose readers all went (forever) or who stopped acknowledging (until then).
  std::map<std::uint64_t, std::chrono::steady_clock::time_point> departed_;
};

}  // namespace gc::service
