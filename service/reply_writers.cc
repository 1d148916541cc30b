#include "service/reply_writers.h"

#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"

namespace gc::service {

using protocol::Calculation;
using protocol::check_dds;
using protocol::Entity;

ReplyWriters::ReplyWriters(dds_entity_t participant, std::array<dds_entity_t, 5> reply_topics,
                           std::string instance_tag)
    : participant_(participant),
      reply_topics_(reply_topics),
      instance_tag_(std::move(instance_tag)) {}

dds_entity_t ReplyWriters::writer_locked(const Key& key) {
  Writer& entry = writers_[key];
  if (!entry.writer) {
    const protocol::Qos partition = protocol::partition_qos(protocol::reply_partition(key.first));
    entry.publisher =
        Entity(check_dds(dds_create_publisher(participant_, partition.get(), nullptr),
                         "dds_create_publisher"));
    const protocol::Qos qos = protocol::tagged_reply_writer_qos(instance_tag_);
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
  if (next == writers_.end() || next->first.first != client_id) departed_.insert(client_id);
}

void ReplyWriters::mark_departed(std::uint64_t client_id) {
  std::lock_guard lock(mutex_);
  departed_.insert(client_id);
}

dds_entity_t ReplyWriters::matched_writer(std::uint64_t client_id, Calculation calculation,
                                          std::chrono::steady_clock::time_point deadline) {
  dds_entity_t writer = 0;
  {
    std::lock_guard lock(mutex_);
    if (departed_.count(client_id) != 0) return 0;
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
