#include "service/reply_writers.h"

#include <set>

#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"

namespace gc::service {

using protocol::Calculation;
using protocol::check_dds;
using protocol::Entity;

ReplyWriters::ReplyWriters(dds_entity_t participant, std::array<dds_entity_t, 5> reply_topics,
                           std::string instance_tag, double max_blocking_s)
    : participant_(participant),
      reply_topics_(reply_topics),
      instance_tag_(std::move(instance_tag)),
      max_blocking_s_(max_blocking_s) {}

dds_entity_t ReplyWriters::writer_locked(const Key& key) {
  Writer& entry = writers_[key];
  if (!entry.writer) {
    const protocol::Qos partition = protocol::partition_qos(protocol::reply_partition(key.first));
    entry.publisher =
        Entity(check_dds(dds_create_publisher(participant_, partition.get(), nullptr),
                         "dds_create_publisher"));
    const protocol::Qos qos = protocol::tagged_reply_writer_qos(instance_tag_, max_blocking_s_);
    entry.writer = Entity(check_dds(
        dds_create_writer(entry.publisher.get(), reply_topics_[key.second], qos.get(), nullptr),
        "dds_create_writer"));
  }
  return entry.writer.get();
}

void ReplyWriters::reader_appeared(std::uint64_t client_id, Calculation calculation) {
  std::lock_guard lock(mutex_);
  const Key key{client_id, static_cast<int>(protocol::index_of(calculation))};
  departed_.erase(client_id);
  writer_locked(key);
  writers_[key].readers += 1;
}

void ReplyWriters::reader_gone(std::uint64_t client_id, Calculation calculation) {
  std::lock_guard lock(mutex_);
  const auto found = writers_.find({client_id, static_cast<int>(protocol::index_of(calculation))});
  if (found == writers_.end()) return;
  if (--found->second.readers > 0) return;
  writers_.erase(found);
  const auto next = writers_.lower_bound({client_id, 0});
  if (next == writers_.end() || next->first.first != client_id) {
    departed_[client_id] = std::chrono::steady_clock::time_point::max();  // ids are never reused
  }
}

void ReplyWriters::mark_departed(std::uint64_t client_id, double hold_s) {
  std::lock_guard lock(mutex_);
  auto& until = departed_[client_id];
  until = std::max(until, std::chrono::steady_clock::now() +
                              std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                  std::chrono::duration<double>(hold_s)));
}

dds_entity_t ReplyWriters::matched_writer(std::uint64_t client_id, Calculation calculation,
                                          std::chrono::steady_clock::time_point deadline) {
  dds_entity_t writer = 0;
  {
    std::lock_guard lock(mutex_);
    const auto departed = departed_.find(client_id);
    if (departed != departed_.end()) {
      if (std::chrono::steady_clock::now() < departed->second) return 0;
      departed_.erase(departed);
    }
    writer = writer_locked({client_id, static_cast<int>(protocol::index_of(calculation))});
  }
  const bool matched =
      protocol::wait_until([&] { return protocol::matched_reader_count(writer) > 0; }, deadline);
  return matched ? writer : 0;
}

std::size_t ReplyWriters::clients() const {
  std::lock_guard lock(mutex_);
  std::set<std::uint64_t> clients;
  for (const auto& [key, writer] : writers_) clients.insert(key.first);
  return clients.size();
}

}  // namespace gc::service
