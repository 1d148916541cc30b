// The implementation of gc::client::Client (client/client.h, the public API and its
// documentation): DDS entities, discovery, pending requests. Not installed.
#pragma once

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "client/client_error.h"
#include "client/client_types.h"
#include "client/reply_error.h"
#include "protocol/calculation_traits.h"
#include "protocol/dds_entity.h"
#include "protocol/requests.h"
#include "protocol/samples.h"
#include "protocol/wire_requests.h"
#include "protocol/wire_results.h"

namespace gc::client {

class ClientCore {
 public:
  using Clock = std::chrono::steady_clock;

  /// Joins the domain and starts discovering instances. Throws protocol::DdsError.
  explicit ClientCore(ClientOptions options);
  /// Fails the pending requests with ClientClosed and leaves the domain.
  ~ClientCore();
  ClientCore(const ClientCore&) = delete;
  ClientCore& operator=(const ClientCore&) = delete;

  template <protocol::Calculation kCalculation>
  using Callback =
      std::function<void(Outcome<typename protocol::CalculationTraits<kCalculation>::Result>)>;

  /// Sends `request` (waiting, like call_async, for a ready instance) and returns; `done` is
  /// called once with the result or the error: in Cyclone's receive thread as the reply arrives
  /// (no thread hand-off, as in ddsperf's listener mode), in this client's own thread for a
  /// timeout or ClientClosed, or before call_then returns when no instance was ready in time.
  /// It must not block or throw. It may send the next request of a calculation that has just
  /// been answered (an instance is ready, so that send does not wait for discovery).
  /// `deadline`: when the call fails with Timeout if no reply has come (discovery included).
  template <protocol::Calculation kCalculation>
  void call_then(const typename protocol::CalculationTraits<kCalculation>::Request& request,
                 Callback<kCalculation> done, Clock::time_point deadline);

  /// Waits until some instance is ready to take `calculation`; false at `timeout`.
  bool wait_for_service(protocol::Calculation calculation, std::chrono::milliseconds timeout);
  /// Live instances known from the status topic.
  std::vector<InstanceInfo> instances() const;
  /// The definition of catalogue coupling `name` as a live instance announces it; nullopt when
  /// no known instance serves that name.
  std::optional<CouplingDefinition> catalogue_definition(const std::string& name) const;
  ClientCounters counters() const;
  std::uint64_t client_id() const { return client_id_; }
  const ClientOptions& options() const { return options_; }
  const std::string& dds_configuration() const { return dds_configuration_; }

 private:
  struct Pending;
  struct Instance;

  /// Registers `pending` under a new sequence number and sends it (waiting for a ready instance
  /// until its deadline). `write` writes the request sample with that sequence number.
  void send(std::uint64_t sequence, Pending pending);
  /// The error for a reply reader DDS Security refused (a client id prefix not this identity's).
  protocol::DdsError reply_reader_refused(dds_return_t code) const;
  std::uint64_t next_sequence();
  /// A request writer or reply reader matched or lost a peer: wake the callers waiting for a
  /// ready instance.
  void matching_changed();
  void receive_loop();
  template <protocol::Calculation kCalculation>
  void take_replies(dds_entity_t reader);
  /// Creates `calculation`'s reply reader and request writers on its first use. A client makes
  /// only the endpoints it uses (rule 2 of docs/protocol.md), and the service a reply writer
  /// only for those: with a hundred clients discovering at once every endpoint counts, since
  /// each is announced to every participant (docs/benchmarks.md, "Discovery at scale").
  void use_locked(protocol::Calculation calculation);
  void create_request_writer_locked(Instance& instance, std::size_t calculation_index);
  void take_status();
  /// Fails requests past their deadline, sends orphaned ones (instance gone) to another and
  /// writes deferred ones (a full window); returns when the receive loop must next look: a
  /// deadline, a resend, or kTick while a request waits for a ready instance.
  Clock::time_point maintain();
  /// Writing request `sequence` failed with `rc`: it is written again from the receive loop,
  /// to another instance if its own went (a deleted writer), after kWindowRetry if the window
  /// was full (DDS_RETCODE_TIMEOUT; counted as deferred).
  void write_failed(std::uint64_t sequence, dds_return_t rc);
  /// `pending` is sent to `instance`: one more request in flight (kMaxInFlight).
  void assign_locked(Pending& pending, std::uint64_t instance);
  /// `pending` is no longer in flight (answered, failed, or its instance went): room for another.
  void release_locked(Pending& pending);
  /// Registers `pending` for the receive loop to send (a reply callback found no room).
  void defer_locked(std::uint64_t sequence, Pending pending);
  Instance* pick_ready_locked(protocol::Calculation calculation);
  bool ready_locked(Instance& instance, protocol::Calculation calculation);

  ClientOptions options_;
  std::uint64_t client_id_;
  std::string dds_configuration_;  ///< protocol::describe() of the configuration joined with
  protocol::Entity participant_;
  std::array<protocol::Entity, gc::protocol::kCalculationCount> request_topics_;
  std::array<protocol::Entity, gc::protocol::kCalculationCount> reply_topics_;
  protocol::Entity status_topic_;
  protocol::Entity reply_subscriber_;
  std::array<protocol::Entity, gc::protocol::kCalculationCount> reply_readers_;  ///< created on first use (use_locked)
  protocol::Entity status_subscriber_;
  protocol::Entity status_reader_;
  protocol::Entity guard_;
  protocol::Entity waitset_;

  mutable std::mutex mutex_;
  std::condition_variable instances_changed_;
  std::map<std::uint64_t, std::unique_ptr<Instance>> instances_;
  std::map<dds_instance_handle_t, std::uint64_t> status_handles_;
  std::map<std::uint64_t, Pending> pending_;
  std::uint64_t sequence_ = 0;
  std::size_t in_flight_ = 0;  ///< pending_ entries sent and not answered (instance != 0)
  std::size_t round_robin_ = 0;
  /// When the receive loop next wakes on its own (set by maintain()); a request due sooner wakes it.
  Clock::time_point loop_wakes_at_ = Clock::time_point::max();
  ClientCounters counters_;
  bool closing_ = false;
  std::thread receiver_;
};

// ---- implementation of the templates ----------------------------------------------------------

struct ClientCore::Pending {
  protocol::Calculation calculation{};
  std::uint64_t instance = 0;  ///< where it was sent; 0 while waiting to be (re)sent
  Clock::time_point deadline;
  std::chrono::milliseconds timeout{0};  ///< deadline - the call, for the Timeout's message
  Clock::time_point resend_at;  ///< when instance == 0: not before this
  bool deferred = false;        ///< not written yet: its last write found the window full
  std::function<dds_return_t(dds_entity_t writer)> write;
  std::function<void(const void* wire_reply)> deliver;
  std::function<void(std::exception_ptr)> fail;
};

template <protocol::Calculation kCalculation>
void ClientCore::call_then(const typename protocol::CalculationTraits<kCalculation>::Request& request,
                       Callback<kCalculation> done, Clock::time_point deadline) {
  using T = protocol::CalculationTraits<kCalculation>;
  using Result = typename T::Result;
  auto sample = std::make_shared<protocol::OwnedSample<typename T::WireRequest>>(T::request_type());
  protocol::to_wire(request, sample->get());
  const std::uint64_t sequence = next_sequence();
  sample->get().correlation.client_id = client_id_;
  sample->get().correlation.sequence_number = sequence;

  auto callback = std::make_shared<Callback<kCalculation>>(std::move(done));
  Pending pending;
  pending.calculation = kCalculation;
  pending.deadline = deadline;
  pending.timeout = std::max(std::chrono::milliseconds(0),
                             std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()));
  pending.write = [sample](dds_entity_t writer) { return dds_write(writer, &sample->get()); };
  pending.deliver = [callback](const void* wire) {
    const auto& reply = *static_cast<const typename T::WireReply*>(wire);
    Outcome<Result> outcome;
    try {
      if (reply.status != gearcoupling_STATUS_OK) {
        throw_reply_error(reply.status, reply.field, reply.message);
      }
      outcome.result = protocol::from_wire(reply.result);
    } catch (...) {
      outcome.error = std::current_exception();
    }
    (*callback)(std::move(outcome));
  };
  pending.fail = [callback](std::exception_ptr error) { (*callback)({std::nullopt, error}); };
  send(sequence, std::move(pending));
}

}  // namespace gc::client
