#include "service/reply_writers.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <set>

#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"

#include <spdlog/spdlog.h>

namespace gc::service {

using protocol::Calculation;
using protocol::check_dds;
using protocol::Entity;

namespace {

/// departed_ and held_ entries whose time is up are swept once there are this many: neither a
/// flood of made-up client ids nor clients that come and go may grow them without bound.
constexpr std::size_t kDepartedPruneSize = 4096;

ReplyWriters::Clock::time_point after(double s) {
  return ReplyWriters::Clock::now() + std::chrono::duration_cast<ReplyWriters::Clock::duration>(
                                          std::chrono::duration<double>(s));
}

}  // namespace

ParticipantKey participant_key_of(const dds_guid_t& guid) {
  ParticipantKey key{};
  static_assert(sizeof(guid.v) == sizeof(key));
  std::memcpy(key.data(), guid.v, key.size());
  return key;
}

ReplyWriters::ReplyWriters(MakeDomain make_domain, std::string instance_tag,
                           std::size_t max_parked, std::function<void()> on_first_parked,
                           double departed_memory_s, std::size_t writers_per_domain,
                           double moved_writer_linger_s, double move_give_up_s)
    : make_domain_(std::move(make_domain)),
      instance_tag_(std::move(instance_tag)),
      writers_per_domain_(std::max<std::size_t>(writers_per_domain, 1)),
      moved_writer_linger_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(moved_writer_linger_s))),
      move_give_up_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(move_give_up_s))),
      max_parked_(max_parked),
      on_first_parked_(std::move(on_first_parked)),
      departed_memory_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(departed_memory_s))),
      prune_at_(kDepartedPruneSize),
      current_(std::make_shared<Generation>(Generation{make_domain_(), 0})) {}

std::shared_ptr<ReplyWriters::Generation> ReplyWriters::generation_for_new_writer() {
  if (current_->writers_made >= writers_per_domain_) {
    auto next = std::make_shared<Generation>(Generation{make_domain_(), 0});
    std::shared_ptr<Generation> replaced;  // released after mutex_: it may be the last reference
    std::lock_guard lock(mutex_);
    replaced = std::exchange(current_, std::move(next));
    replaced_domains_ = true;
    spdlog::info("reply writers: a new reply domain after {} writers in the last one",
                 writers_per_domain_);
  }
  current_->writers_made += 1;
  return current_;
}

ReplyWriters::Endpoint ReplyWriters::make_endpoint(std::shared_ptr<Generation> generation,
                                                   const Key& key) const {
  const protocol::Qos partition = protocol::partition_qos(protocol::reply_partition(key.first));
  Endpoint endpoint{std::move(generation), {}, {}};
  const ReplyDomain& domain = *endpoint.generation->domain;
  endpoint.publisher = Entity(check_dds(
      dds_create_publisher(domain.participant(), partition.get(), nullptr), "dds_create_publisher"));
  // KEEP_LAST (protocol::reply_history_depth): the writer keeps only its latest replies for
  // readers that have not acknowledged them and never waits for one, so no reader in the
  // client's partition, the client's own or another process's that never reads, can hold it
  // (issue 38). Max blocking time 0 as well: were a write ever to find the writer's window full,
  // it would return DDS_RETCODE_TIMEOUT at once and the reply go to the ReplyBacklog.
  const protocol::Qos qos = protocol::tagged_reply_writer_qos(
      instance_tag_, protocol::kAllCalculations[key.second], 0.0);
  endpoint.writer = Entity(check_dds(dds_create_writer(endpoint.publisher.get(),
                                                       domain.reply_topic(key.second), qos.get(),
                                                       nullptr),
                                     "dds_create_writer"));
  return endpoint;
}

void ReplyWriters::reader_appeared(std::uint64_t client_id, Calculation calculation,
                                   const ParticipantKey& owner) {
  const Key key{client_id, static_cast<int>(protocol::index_of(calculation))};
  {
    std::lock_guard lock(mutex_);
    departed_.erase(client_id);
    held_.erase(held_.lower_bound({client_id, ParticipantKey{}}),
                held_.upper_bound({client_id, ParticipantKey{
                    0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff,
                    0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff}}));
    owners_[client_id][owner] += 1;
    Writer& entry = writers_[key];
    entry.readers += 1;
    if (entry.endpoint.writer) return;
  }
  // Created without mutex_: the request listener takes it (admit), and creating a writer may
  // wait for Cyclone's receive thread, which runs that listener (announcing the writer is a
  // reliable write). Only the dispatch loop creates and deletes writers, so none races this.
  Endpoint endpoint = make_endpoint(generation_for_new_writer(), key);
  std::lock_guard lock(mutex_);
  writers_[key].endpoint = std::move(endpoint);
}

void ReplyWriters::reader_gone(std::uint64_t client_id, Calculation calculation,
                               const ParticipantKey& owner) {
  Writer gone;  // deleted after mutex_ is released, for the reason given in reader_appeared
  std::lock_guard lock(mutex_);
  if (const auto owners = owners_.find(client_id); owners != owners_.end()) {
    if (const auto found = owners->second.find(owner);
        found != owners->second.end() && --found->second <= 0) {
      owners->second.erase(found);
    }
    if (owners->second.empty()) owners_.erase(owners);
  }
  const auto found = writers_.find({client_id, static_cast<int>(protocol::index_of(calculation))});
  if (found == writers_.end()) return;
  if (--found->second.readers > 0) return;
  gone = std::move(found->second);  // its domain too, if it is a replaced one's last writer
  writers_.erase(found);
  const auto next = writers_.lower_bound({client_id, 0});
  if (next == writers_.end() || next->first.first != client_id) {
    const Clock::time_point now = Clock::now();
    departed_[client_id] = now + departed_memory_;
    prune_locked(now);
  }
}

void ReplyWriters::prune_locked(Clock::time_point now) {
  if (departed_.size() < prune_at_ && held_.size() < prune_at_) return;
  std::erase_if(departed_, [now](const auto& entry) { return entry.second <= now; });
  std::erase_if(held_, [now](const auto& entry) { return entry.second <= now; });
  prune_at_ = std::max(kDepartedPruneSize, 2 * std::max(departed_.size(), held_.size()));
}

void ReplyWriters::mark_departed(std::uint64_t client_id, double hold_s) {
  std::lock_guard lock(mutex_);
  mark_departed_locked(client_id, after(hold_s));
}

void ReplyWriters::mark_departed_locked(std::uint64_t client_id, Clock::time_point until) {
  auto& held = departed_[client_id];
  held = std::max(held, until);
  prune_locked(Clock::now());
}

bool ReplyWriters::departed_locked(std::uint64_t client_id, Clock::time_point now) {
  const auto departed = departed_.find(client_id);
  if (departed == departed_.end()) return false;
  if (now < departed->second) return true;
  departed_.erase(departed);
  return false;
}

bool ReplyWriters::held_locked(std::uint64_t client_id, const ParticipantKey& requester,
                               Clock::time_point now) {
  const auto held = held_.find({client_id, requester});
  if (held == held_.end()) return false;
  if (now < held->second) return true;
  held_.erase(held);
  return false;
}

bool ReplyWriters::matched_locked(const Key& key) {
  const auto found = writers_.find(key);
  if (found == writers_.end()) return false;
  Writer& entry = found->second;
  // Matching is asynchronous to the writer's creation, so ask Cyclone until it says yes.
  if (!entry.matched) {
    entry.matched = protocol::matched_reader_count(entry.endpoint.writer.get()) > 0;
  }
  return entry.matched;
}

bool ReplyWriters::reads_own_replies_locked(const Key& key, const ParticipantKey& requester) {
  const auto found = writers_.find(key);
  if (found == writers_.end() || !found->second.endpoint.writer) return false;
  dds_guid_t participant{};
  std::memcpy(participant.v, requester.data(), requester.size());
  // Cyclone has matched the requester's own reply reader, but the dispatch loop has not yet taken
  // its report from the built-in topic: the requester is an owner the loop does not know yet.
  return protocol::matched_with_reader_of(found->second.endpoint.writer.get(), participant);
}

ReplyWriters::Admission ReplyWriters::admit(std::uint64_t client_id, Calculation calculation,
                                            std::uint64_t sequence_number,
                                            const std::optional<ParticipantKey>& requester,
                                            Job& job, Clock::time_point park_until) {
  bool first = false;
  const ParticipantKey from = requester.value_or(ParticipantKey{});
  {
    std::lock_guard lock(mutex_);
    const Key key{client_id, static_cast<int>(protocol::index_of(calculation))};
    // Someone else's id: the client's readers are known and none is the requester's. Checked
    // before any hold, so a forger is neither parked nor able to spend the client's holds.
    if (const auto owners = owners_.find(client_id);
        owners != owners_.end() && (!requester || owners->second.count(*requester) == 0) &&
        !(requester && reads_own_replies_locked(key, *requester))) {
      return Admission::kForged;
    }
    const Clock::time_point now = Clock::now();
    if (departed_locked(client_id, now) || held_locked(client_id, from, now)) {
      drops_.departed += 1;
      return Admission::kDropped;
    }
    if (matched_locked(key)) return Admission::kRun;
    if (parked_count_ >= max_parked_) {
      drops_.parked_full += 1;
      return Admission::kDropped;
    }
    parked_[key].push_back({sequence_number, from, park_until, std::move(job)});
    first = parked_count_++ == 0;
  }
  if (first && on_first_parked_) on_first_parked_();
  return Admission::kParked;
}

std::vector<ReplyWriters::Job> ReplyWriters::release(Clock::time_point now, double hold_s,
                                                     std::vector<UnmatchedRequest>& expired) {
  std::vector<Job> ready;
  std::lock_guard lock(mutex_);
  for (auto it = parked_.begin(); it != parked_.end();) {
    std::deque<Parked>& queue = it->second;
    const bool matched = matched_locked(it->first);
    while (!queue.empty() && (matched || queue.front().until <= now)) {
      if (matched) {
        ready.push_back(std::move(queue.front().job));
      } else {
        expired.push_back({it->first.first, queue.front().sequence_number,
                           protocol::kAllCalculations[it->first.second]});
        drops_.unmatched += 1;
        auto& held = held_[{it->first.first, queue.front().requester}];
        held = std::max(held, after(hold_s));
      }
      queue.pop_front();
      parked_count_ -= 1;
    }
    it = queue.empty() ? parked_.erase(it) : std::next(it);
  }
  prune_locked(now);
  return ready;
}

std::size_t ReplyWriters::parked() const {
  std::lock_guard lock(mutex_);
  return parked_count_;
}

AdmissionDrops ReplyWriters::drops() const {
  std::lock_guard lock(mutex_);
  return drops_;
}

dds_entity_t ReplyWriters::writer(std::uint64_t client_id, Calculation calculation) const {
  std::lock_guard lock(mutex_);
  const auto found = writers_.find({client_id, static_cast<int>(protocol::index_of(calculation))});
  return found == writers_.end() ? 0 : found->second.endpoint.writer.get();
}

bool ReplyWriters::move_writers(Clock::time_point now) {
  std::vector<Lingering> over;  // deleted after mutex_ is released (reader_appeared says why)
  std::vector<Key> to_move;
  std::shared_ptr<Generation> current;
  bool moving = false;  // a successor to make or to wait for
  {
    std::lock_guard lock(mutex_);
    if (!replaced_domains_ && lingering_.empty()) return false;
    current = current_;
    bool outside_current = false;
    for (auto& [key, entry] : writers_) {
      if (!entry.endpoint.writer || entry.endpoint.generation == current) continue;
      outside_current = true;
      if (entry.move_again > now) continue;
      if (!entry.successor.writer) {
        if (to_move.size() < kMovesPerCall) to_move.push_back(key);
        moving = true;
        continue;
      }
      // The successor takes over once it reaches every reader the old writer reaches: the
      // client sees no gap, as both are this instance's writers in its partition.
      if (protocol::matched_reader_count(entry.successor.writer.get()) <
          protocol::matched_reader_count(entry.endpoint.writer.get())) {
        if (now - entry.successor_made < move_give_up_) {
          moving = true;
        } else {
          spdlog::info("client {:016x}: its reply reader has not matched this instance's new reply domain in {} s; "
                       "it stays in the old one, and the move is tried again later",
                       key.first, std::chrono::duration<double>(move_give_up_).count());
          over.push_back({std::exchange(entry.successor, Endpoint{}), now});
          entry.move_again = now + 10 * move_give_up_;
        }
        continue;
      }
      lingering_.push_back({std::move(entry.endpoint), now + moved_writer_linger_});
      entry.endpoint = std::exchange(entry.successor, Endpoint{});
    }
    replaced_domains_ = outside_current;
    const auto first_over = std::partition(lingering_.begin(), lingering_.end(),
                                           [now](const Lingering& l) { return l.until > now; });
    std::move(first_over, lingering_.end(), std::back_inserter(over));
    lingering_.erase(first_over, lingering_.end());
  }
  for (const Key& key : to_move) {
    Endpoint successor = make_endpoint(current, key);  // without mutex_, as in reader_appeared
    std::lock_guard lock(mutex_);
    const auto found = writers_.find(key);
    // The client may have left meanwhile: the successor then goes, after mutex_, with `over`.
    if (found == writers_.end() || !found->second.endpoint.writer ||
        found->second.successor.writer || found->second.endpoint.generation == current) {
      over.push_back({std::move(successor), now});
      continue;
    }
    found->second.successor = std::move(successor);
    found->second.successor_made = now;
  }
  std::lock_guard lock(mutex_);
  return moving || !lingering_.empty();
}

std::size_t ReplyWriters::domains() const {
  std::lock_guard lock(mutex_);
  std::set<const Generation*> alive{current_.get()};
  for (const auto& [key, writer] : writers_) {
    alive.insert(writer.endpoint.generation.get());
    alive.insert(writer.successor.generation.get());
  }
  for (const Lingering& lingering : lingering_) alive.insert(lingering.endpoint.generation.get());
  alive.erase(nullptr);
  return alive.size();
}

std::size_t ReplyWriters::remembered_departures() const {
  std::lock_guard lock(mutex_);
  return departed_.size() + held_.size();
}

std::size_t ReplyWriters::clients() const {
  std::lock_guard lock(mutex_);
  std::set<std::uint64_t> clients;
  for (const auto& [key, writer] : writers_) clients.insert(key.first);
  return clients.size();
}

}  // namespace gc::service
