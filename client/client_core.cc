#include "client/client_core.h"

#include <algorithm>
#include <thread>

#include "client/instance_info.h"

#include <fmt/format.h>

#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/random_id.h"
#include "protocol/topics.h"
#include "protocol/wire_inputs.h"

namespace gc::client {

using protocol::Calculation;
using protocol::check_dds;
using protocol::Entity;

namespace {

using Clock = ClientCore::Clock;

/// Writes with `write` to `writer`. A full window (DDS_RETCODE_TIMEOUT: the writers never block)
/// is waited out as a blocking write would, until the service has acknowledged what was sent,
/// at most until `until`; then written again. Never from a reply callback: the acknowledgements
/// come in through the very thread that runs it.
dds_return_t write_when_acknowledged(const std::function<dds_return_t(dds_entity_t)>& write,
                                     dds_entity_t writer, Clock::time_point until) {
  dds_return_t rc = write(writer);
  while (rc == DDS_RETCODE_TIMEOUT && Clock::now() < until) {
    const auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(until - Clock::now());
    dds_wait_for_acks(writer, static_cast<dds_duration_t>(left.count()));
    rc = write(writer);
  }
  return rc;
}

/// A disposed status means a graceful shutdown: the instance answered what it had before
/// disposing, so give those replies this long to arrive before sending the rest elsewhere.
constexpr std::chrono::milliseconds kDisposedResendDelay{500};
/// How often the receive loop looks for a ready instance while a request waits for one.
constexpr std::chrono::milliseconds kTick{10};
/// Longest the receive loop sleeps when nothing is due: otherwise it wakes only for a request's
/// deadline, a status sample or the guard condition. A thread woken a hundred times a second
/// for nothing costs round trips on a busy host (docs/architecture.md, "Few wake-ups besides the round trip's own").
constexpr std::chrono::seconds kIdleWake{1};
/// How soon the receive loop tries again a write deferred by a reply callback (a full window).
constexpr std::chrono::microseconds kWindowRetry{200};
/// How long the receive loop waits for acknowledgements before writing a deferred request again:
/// it also fails requests past their deadline, so it waits a short while only.
constexpr std::chrono::milliseconds kAckWait{50};
/// Requests one client has written and not yet had answered, at most: half the replies the
/// service holds for one client whose window is full (kMaxBackloggedRepliesPerClient, 512, in
/// service/service.cc), past which it drops them. A burst beyond it waits (docs/protocol.md).
constexpr std::size_t kMaxInFlight = 256;
/// Set while this thread runs a reply callback (Cyclone's receive thread): a write made from it
/// must not wait for acknowledgements, which only this very thread would read.
thread_local bool in_reply_callback = false;
/// Longest a caller waiting for a ready instance sleeps between looks. Matching events wake it
/// at once (matched listeners); this only bounds a wake-up lost to the race between a look and
/// the wait. Looking costs a copy of every matched writer's QoS: a hundred clients discovering
/// at once and looking every millisecond kept a 2-core host saturated (docs/benchmarks.md).
constexpr std::chrono::milliseconds kReadyPoll{20};

}  // namespace

struct ClientCore::Instance {
  InstanceInfo info;
  Entity publisher;  ///< in the instance's request partition
  std::array<Entity, gc::protocol::kCalculationCount> writers;
  std::array<bool, gc::protocol::kCalculationCount> ready{};  ///< both directions matched for this calculation
};

ClientCore::ClientCore(ClientOptions options)
    : options_(options),
      client_id_(protocol::random_id_with_prefix(options.client_id_prefix)),
      dds_configuration_(protocol::describe(protocol::dds_config())),
      participant_(protocol::create_participant(options.domain, protocol::dds_config())),
      request_topics_(protocol::make_request_topics(participant_.get())),
      reply_topics_(protocol::make_reply_topics(participant_.get())),
      status_topic_(protocol::make_status_topic(participant_.get())) {
  waitset_ = Entity(check_dds(dds_create_waitset(participant_.get()), "dds_create_waitset"));
  const protocol::Qos reply_partition =
      protocol::partition_qos(protocol::reply_partition(client_id_));
  reply_subscriber_ = Entity(check_dds(
      dds_create_subscriber(participant_.get(), reply_partition.get(), nullptr),
      "dds_create_subscriber(replies)"));
  // Reply readers are made on a calculation's first use; under DDS Security, find out now, not
  // at the first call, whether this identity may read its reply partition (a wrong prefix).
  if (options_.client_id_prefix != 0) {
    const protocol::Qos qos = protocol::request_reply_qos();
    const dds_entity_t probe = dds_create_reader(
        reply_subscriber_.get(), reply_topics_[0].get(), qos.get(), nullptr);
    if (probe == DDS_RETCODE_NOT_ALLOWED_BY_SECURITY) throw reply_reader_refused(probe);
    if (probe > 0) dds_delete(probe);
  }
  const protocol::Qos status_partition = protocol::partition_qos(protocol::kStatusPartition);
  status_subscriber_ = Entity(check_dds(
      dds_create_subscriber(participant_.get(), status_partition.get(), nullptr),
      "dds_create_subscriber(status)"));
  const protocol::Qos status_qos = protocol::status_reader_qos();
  status_reader_ = Entity(check_dds(
      dds_create_reader(status_subscriber_.get(), status_topic_.get(), status_qos.get(), nullptr),
      "dds_create_reader(status)"));
  dds_set_status_mask(status_reader_.get(), DDS_DATA_AVAILABLE_STATUS);
  check_dds(dds_waitset_attach(waitset_.get(), status_reader_.get(), 0), "dds_waitset_attach");
  guard_ = Entity(check_dds(dds_create_guardcondition(participant_.get()),
                            "dds_create_guardcondition"));
  check_dds(dds_waitset_attach(waitset_.get(), guard_.get(), 0), "dds_waitset_attach");
  receiver_ = std::thread([this] { receive_loop(); });
}

ClientCore::~ClientCore() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  instances_changed_.notify_all();
  dds_set_guardcondition(guard_.get(), true);
  receiver_.join();
  for (const Entity& reader : reply_readers_) {
    if (reader) dds_set_listener(reader.get(), nullptr);
  }
  std::map<std::uint64_t, Pending> pending;
  {
    std::lock_guard lock(mutex_);
    pending.swap(pending_);
  }
  for (auto& [sequence, p] : pending) {
    p.fail(std::make_exception_ptr(ClientClosed(fmt::format(
        "{} request {} abandoned: the client closed", protocol::to_string(p.calculation),
        sequence))));
  }
}

void ClientCore::use_locked(Calculation calculation) {
  const std::size_t i = protocol::index_of(calculation);
  if (reply_readers_[i]) return;
  // Replies are taken in Cyclone's delivery thread (a data-available listener) and handed
  // straight to the waiting caller: no extra thread between the network and the caller.
  protocol::for_each_calculation([&](auto c) {
    constexpr Calculation kCalculation = decltype(c)::value;
    if (kCalculation != calculation) return;
    dds_listener_t* listener = dds_create_listener(this);
    dds_lset_data_available(listener, [](dds_entity_t reader, void* client) {
      static_cast<ClientCore*>(client)->take_replies<kCalculation>(reader);
    });
    dds_lset_subscription_matched(listener, [](dds_entity_t, dds_subscription_matched_status_t,
                                               void* client) {
      static_cast<ClientCore*>(client)->matching_changed();
    });
    const protocol::Qos qos = protocol::request_reply_qos();
    const dds_entity_t reader =
        dds_create_reader(reply_subscriber_.get(), reply_topics_[i].get(), qos.get(), listener);
    dds_delete_listener(listener);
    if (reader == DDS_RETCODE_NOT_ALLOWED_BY_SECURITY) throw reply_reader_refused(reader);
    reply_readers_[i] = Entity(check_dds(reader, "dds_create_reader(reply)"));
  });
  for (auto& [id, instance] : instances_) create_request_writer_locked(*instance, i);
}

void ClientCore::create_request_writer_locked(Instance& instance, std::size_t i) {
  // Max blocking time 0: a full window (unacknowledged requests over the writer history cache's
  // high-water mark) returns DDS_RETCODE_TIMEOUT at once instead of blocking (send()).
  const protocol::Qos qos = protocol::request_reply_qos(0.0);
  dds_listener_t* listener = dds_create_listener(this);
  dds_lset_publication_matched(listener, [](dds_entity_t, dds_publication_matched_status_t,
                                            void* client) {
    static_cast<ClientCore*>(client)->matching_changed();
  });
  instance.writers[i] = Entity(check_dds(
      dds_create_writer(instance.publisher.get(), request_topics_[i].get(), qos.get(), listener),
      "dds_create_writer(request)"));
  dds_delete_listener(listener);
}

void ClientCore::matching_changed() {
  // Without mutex_: Cyclone may call this inside dds_create_writer, which take_status() calls
  // with mutex_ held. A wake-up lost to that is made up by kReadyPoll.
  instances_changed_.notify_all();
}

std::uint64_t ClientCore::next_sequence() {
  std::lock_guard lock(mutex_);
  return ++sequence_;
}

protocol::DdsError ClientCore::reply_reader_refused(dds_return_t code) const {
  return protocol::DdsError(
      fmt::format("dds_create_reader(reply) in partition \"{}\": this participant's DDS Security "
                  "permissions do not allow reading it; the client id prefix ({:08x}, "
                  "--client-id-prefix or GC_CLIENT_ID_PREFIX) must be the client_id_prefix "
                  "written next to the identity's certificate",
                  protocol::reply_partition(client_id_), options_.client_id_prefix),
      code);
}

bool ClientCore::ready_locked(Instance& instance, Calculation calculation) {
  const std::size_t i = protocol::index_of(calculation);
  if (!instance.ready[i] && instance.writers[i]) {
    instance.ready[i] =
        protocol::matched_reader_count(instance.writers[i].get()) > 0 &&
        protocol::matched_with_tagged_writer(reply_readers_[i].get(),
                                             protocol::hex_id(instance.info.id));
  }
  return instance.ready[i];
}

ClientCore::Instance* ClientCore::pick_ready_locked(Calculation calculation) {
  std::vector<Instance*> candidates;
  for (auto& [id, instance] : instances_) {
    if (instance->info.accepting) candidates.push_back(instance.get());
  }
  if (candidates.empty()) return nullptr;
  const std::size_t start = round_robin_++;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    Instance* instance = candidates[(start + k) % candidates.size()];
    if (ready_locked(*instance, calculation)) return instance;
  }
  return nullptr;
}

void ClientCore::assign_locked(Pending& pending, std::uint64_t instance) {
  if (pending.instance == 0) in_flight_ += 1;
  pending.instance = instance;
}

void ClientCore::release_locked(Pending& pending) {
  if (pending.instance == 0) return;
  pending.instance = 0;
  in_flight_ -= 1;
  instances_changed_.notify_all();  // a sender may wait for room (kMaxInFlight)
}

void ClientCore::defer_locked(std::uint64_t sequence, Pending pending) {
  counters_.deferred += 1;
  pending.deferred = true;
  pending.resend_at = Clock::now();
  pending_.emplace(sequence, std::move(pending));
  dds_set_guardcondition(guard_.get(), true);
}

void ClientCore::write_failed(std::uint64_t sequence, dds_return_t rc) {
  {
    std::lock_guard lock(mutex_);
    const auto found = pending_.find(sequence);
    if (found == pending_.end()) return;  // answered or failed meanwhile
    Pending& pending = found->second;
    counters_.sent -= 1;
    release_locked(pending);
    if (rc == DDS_RETCODE_TIMEOUT) {
      // The window was full: the receive loop writes it once acknowledgements have come in.
      counters_.deferred += 1;
      pending.deferred = true;
      pending.resend_at = Clock::now() + kWindowRetry;
    }
    // Otherwise the instance went while writing (its writer was deleted): send it elsewhere.
  }
  dds_set_guardcondition(guard_.get(), true);
}

void ClientCore::send(std::uint64_t sequence, Pending pending) {
  std::unique_lock lock(mutex_);
  use_locked(pending.calculation);
  for (;;) {
    if (closing_) {
      lock.unlock();
      pending.fail(std::make_exception_ptr(ClientClosed("the client is closing")));
      return;
    }
    const bool room = in_flight_ < kMaxInFlight;
    if (!room && in_reply_callback) {  // a callback must not wait: the receive loop sends it
      defer_locked(sequence, std::move(pending));
      return;
    }
    Instance* instance = room ? pick_ready_locked(pending.calculation) : nullptr;
    if (instance != nullptr) {
      const dds_entity_t writer =
          instance->writers[protocol::index_of(pending.calculation)].get();
      assign_locked(pending, instance->info.id);
      auto write = pending.write;
      const Clock::time_point deadline = pending.deadline;
      // The receive loop sleeps until loop_wakes_at_: wake it if this deadline comes first.
      const bool wake_loop = deadline < loop_wakes_at_;
      pending_.emplace(sequence, std::move(pending));
      counters_.sent += 1;
      lock.unlock();
      if (wake_loop) dds_set_guardcondition(guard_.get(), true);
      // A full window: a caller outside the receive thread waits for acknowledgements here
      // (back-pressure, as a blocking write); a reply callback defers the write (write_failed).
      const dds_return_t rc = in_reply_callback ? write(writer)
                                                : write_when_acknowledged(write, writer, deadline);
      if (rc < 0) write_failed(sequence, rc);
      return;
    }
    const Clock::time_point now = Clock::now();
    if (now >= pending.deadline) {
      counters_.timeouts += 1;
      const std::size_t known = instances_.size();
      lock.unlock();
      pending.fail(std::make_exception_ptr(Timeout(
          room ? fmt::format("{} request {}: {}", protocol::to_string(pending.calculation),
                             sequence,
                             protocol::no_instance_message(options_.domain, pending.timeout,
                                                           dds_configuration_, known))
               : fmt::format("{} request {}: not sent within {} ms: {} requests of this client "
                             "were in flight all that time, none answered",
                             protocol::to_string(pending.calculation), sequence,
                             pending.timeout.count(), kMaxInFlight))));
      return;
    }
    // Woken by status samples, matching events (matching_changed()) and answers (room).
    instances_changed_.wait_until(lock, std::min(pending.deadline, now + kReadyPoll));
  }
}

bool ClientCore::wait_for_service(Calculation calculation, std::chrono::milliseconds timeout) {
  const Clock::time_point deadline = Clock::now() + timeout;
  std::unique_lock lock(mutex_);
  use_locked(calculation);
  for (;;) {
    for (auto& [id, instance] : instances_) {
      if (instance->info.accepting && ready_locked(*instance, calculation)) return true;
    }
    if (Clock::now() >= deadline || closing_) return false;
    instances_changed_.wait_until(lock, std::min(deadline, Clock::now() + kReadyPoll));
  }
}

std::vector<InstanceInfo> ClientCore::instances() const {
  std::lock_guard lock(mutex_);
  std::vector<InstanceInfo> out;
  for (const auto& [id, instance] : instances_) out.push_back(instance->info);
  return out;
}

std::optional<CouplingDefinition> ClientCore::catalogue_definition(const std::string& name) const {
  std::lock_guard lock(mutex_);
  for (const auto& [id, instance] : instances_) {
    for (const CouplingDefinition& d : instance->info.definitions) if (d.name == name) return d;
  }
  return std::nullopt;
}

ClientCounters ClientCore::counters() const {
  std::lock_guard lock(mutex_);
  return counters_;
}

template <Calculation kCalculation>
void ClientCore::take_replies(dds_entity_t reader) {
  using T = protocol::CalculationTraits<kCalculation>;
  for (;;) {
    protocol::LoanedSamples<typename T::WireReply> samples(reader);
    if (samples.size() == 0) return;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (!samples.info(i).valid_data) continue;
      const typename T::WireReply& reply = samples[i];
      Pending pending;
      {
        std::lock_guard lock(mutex_);
        if (reply.correlation.client_id != client_id_) {
          counters_.foreign += 1;
          continue;
        }
        const auto found = pending_.find(reply.correlation.sequence_number);
        if (found == pending_.end() || found->second.calculation != kCalculation) {
          counters_.duplicates += 1;
          continue;
        }
        release_locked(found->second);
        pending = std::move(found->second);
        pending_.erase(found);
        counters_.replies += 1;
      }
      in_reply_callback = true;
      pending.deliver(&reply);
      in_reply_callback = false;
    }
  }
}

void ClientCore::take_status() {
  for (;;) {
    protocol::LoanedSamples<gearcoupling_ServiceStatus> samples(status_reader_.get());
    if (samples.size() == 0) return;
    // Converted before taking mutex_, which every reply takes on Cyclone's receive thread
    // (take_replies): a status sample a second, with its catalogue, is work for this thread
    // alone, not a wait for the round trip (docs/architecture.md, "No lock of the round trip
    // held by periodic work").
    std::vector<InstanceInfo> infos(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const dds_sample_info_t& info = samples.info(i);
      if (info.instance_state == DDS_IST_ALIVE && info.valid_data) {
        infos[i] = instance_info_from_wire(samples[i]);
      }
    }
    // Instances gone, deleted (their DDS writers with them) only once mutex_ is released:
    // dds_delete waits for Cyclone's receive thread, which may be waiting for mutex_ in
    // take_replies (a deadlock seen when an instance's host was cut off, network_faults_test).
    std::vector<std::unique_ptr<Instance>> gone;
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const dds_sample_info_t& info = samples.info(i);
      if (info.instance_state != DDS_IST_ALIVE) {
        const auto handle = status_handles_.find(info.instance_handle);
        if (handle == status_handles_.end()) continue;
        const std::uint64_t id = handle->second;
        status_handles_.erase(handle);
        if (auto node = instances_.extract(id)) gone.push_back(std::move(node.mapped()));
        const Clock::time_point resend_at =
            Clock::now() + (info.instance_state == DDS_IST_NOT_ALIVE_DISPOSED
                                ? kDisposedResendDelay
                                : std::chrono::milliseconds(0));
        for (auto& [sequence, pending] : pending_) {
          if (pending.instance == id) {
            release_locked(pending);
            pending.resend_at = resend_at;
          }
        }
        continue;
      }
      if (!info.valid_data) continue;
      const gearcoupling_ServiceStatus& status = samples[i];
      status_handles_[info.instance_handle] = status.instance_id;
      auto& instance = instances_[status.instance_id];
      if (!instance) {
        instance = std::make_unique<Instance>();
        instance->info.id = status.instance_id;
        const protocol::Qos partition =
            protocol::partition_qos(protocol::request_partition(status.instance_id));
        instance->publisher = Entity(check_dds(
            dds_create_publisher(participant_.get(), partition.get(), nullptr),
            "dds_create_publisher(requests)"));
        for (std::size_t c = 0; c < instance->writers.size(); ++c) {
          if (reply_readers_[c]) create_request_writer_locked(*instance, c);
        }
      }
      instance->info = std::move(infos[i]);
    }
    instances_changed_.notify_all();
  }
}

ClientCore::Clock::time_point ClientCore::maintain() {
  struct Resend {
    std::uint64_t sequence;
    std::function<dds_return_t(dds_entity_t)> write;
    dds_entity_t writer;
  };
  std::vector<Resend> resends;
  std::vector<std::pair<Pending, std::string>> expired;
  Clock::time_point next = Clock::time_point::max();
  {
    std::lock_guard lock(mutex_);
    const Clock::time_point now = Clock::now();
    for (auto it = pending_.begin(); it != pending_.end();) {
      Pending& pending = it->second;
      if (now >= pending.deadline) {
        counters_.timeouts += 1;
        std::string message = fmt::format(
            "{} request {} (client {}) to instance {}: no reply within {} ms",
            protocol::to_string(pending.calculation), it->first, protocol::hex_id(client_id_),
            pending.instance != 0 ? protocol::hex_id(pending.instance) : "(none left)",
            pending.timeout.count());
        release_locked(pending);
        expired.emplace_back(std::move(pending), std::move(message));
        it = pending_.erase(it);
        continue;
      }
      next = std::min(next, pending.deadline);
      if (pending.instance == 0 && now < pending.resend_at) {
        next = std::min(next, pending.resend_at);
      } else if (pending.instance == 0 && in_flight_ >= kMaxInFlight) {
        next = std::min(next, now + kWindowRetry);  // answers make room soon
      } else if (pending.instance == 0) {  // none ready: the next tick or status sample looks again
        next = std::min(next, now + kTick);
        if (Instance* instance = pick_ready_locked(pending.calculation)) {
          assign_locked(pending, instance->info.id);
          resends.push_back({it->first, pending.write,
                             instance->writers[protocol::index_of(pending.calculation)].get()});
          // A deferred write was never sent: writing it now is its first sending, not a resend.
          if (!pending.deferred) counters_.resent += 1;
          pending.deferred = false;  // set again by write_failed() if the window is still full
          counters_.sent += 1;
        }
      }
      ++it;
    }
    loop_wakes_at_ = std::min(next, now + kIdleWake);
  }
  // A writer whose window stayed full through one kAckWait is not tried again in this round:
  // the loop also fails requests past their deadline and must not wait kAckWait per request.
  std::vector<dds_entity_t> full;
  for (const Resend& resend : resends) {
    const bool skip = std::find(full.begin(), full.end(), resend.writer) != full.end();
    const dds_return_t rc =
        skip ? DDS_RETCODE_TIMEOUT
             : write_when_acknowledged(resend.write, resend.writer, Clock::now() + kAckWait);
    if (rc == DDS_RETCODE_TIMEOUT && !skip) full.push_back(resend.writer);
    if (rc < 0) {
      write_failed(resend.sequence, rc);
      next = std::min(next, Clock::now() + kWindowRetry);
    }
  }
  for (auto& [pending, message] : expired) {
    pending.fail(std::make_exception_ptr(Timeout(message)));
  }
  return next;
}

void ClientCore::receive_loop() {
  Clock::time_point next = Clock::now() + kIdleWake;
  for (;;) {
    // Until the next deadline or resend (maintain()), or something arrives: no periodic wake-up.
    const auto wait = std::clamp(
        std::chrono::duration_cast<std::chrono::nanoseconds>(next - Clock::now()),
        std::chrono::nanoseconds(0), std::chrono::nanoseconds(kIdleWake));
    dds_waitset_wait(waitset_.get(), nullptr, 0, static_cast<dds_duration_t>(wait.count()));
    bool woken = false;  // write_failed() or the destructor set it; reset it to wait again
    dds_take_guardcondition(guard_.get(), &woken);
    {
      std::lock_guard lock(mutex_);
      if (closing_) return;
    }
    take_status();
    next = maintain();
  }
}

}  // namespace gc::client
