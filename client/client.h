// The C++ client of gearcoupling-service (docs/protocol.md, docs/architecture.md).
// Example (compiled by tests/docs/doc_snippets.py, ctest docs.snippets):
//
//   #include <cstdio>
//   #include "client/client.h"
//
//   using gc::protocol::Calculation;
//   gc::client::Client client({.domain = 7, .timeout = std::chrono::seconds(5)});
//   const gc::protocol::JamAngleRequest jam_request{gc::protocol::CatalogueName{"nrel_upwind"}};
//   gc::protocol::JamAngleResult jam = client.call<Calculation::kJamAngle>(jam_request);
//   const gc::protocol::InducedMomentsRequest moments_request{
//       gc::protocol::CatalogueName{"nrel_upwind"}, {1.5e6, jam.jam.angle_rad / 2, 0.0, 0.1}, {}};
//   std::future<gc::InducedMoments> future =   // many in flight
//       client.call_async<Calculation::kInducedMoments>(moments_request);
//   client.call_then<Calculation::kJamAngle>(   // a callback, in Cyclone's receive thread
//       jam_request, [](gc::client::Outcome<gc::protocol::JamAngleResult> outcome) {
//         if (outcome.error) return;   // an exception_ptr: Timeout, InvalidInput, ...
//         std::printf("jam angle %g rad\n", outcome.result->jam.angle_rad);
//       });
//   gc::InducedMoments moments = future.get();   // or throws the error
//   std::vector<gc::protocol::BatchCaseReply> many = client.call_many(   // one request, 2 cases
//       gc::protocol::BatchCalculation::kInducedMoments, {gc::protocol::CatalogueName{"nrel_upwind"}},
//       {}, {{0, {1.5e6, 0.005, 0.0, 0.1}}, {0, {-5.0, 0.005, 0.0, 0.1}}});
//   gc::client::Outcome<gc::InducedMoments> second =   // its error: InvalidInput, torque_nm
//       gc::client::outcome_of<gc::InducedMoments>(many[1]);
//
// Discovery is handled: instances are found through the status topic, and no request is
// written to an instance before this client's request writer has matched the instance's
// request reader and the instance's reply writer (recognised by its USER_DATA) has matched this
// client's reply reader, so the first request is never lost. Requests are spread round-robin
// over the live instances that accept work; when an instance disappears (its status is disposed
// or its liveliness lapses) the requests it had not answered are sent again to another one. A
// reply that arrives for a request already answered is dropped and counted.
//
// Errors: the model's errors come back as the core's exception types with the core's message
// (gc::InvalidInput naming the field, gc::NotConverged), or protocol::ServiceError for the rest;
// a call that gets no reply within ClientOptions::timeout fails with client::Timeout.
// Thread-safe: any number of threads may call at once.
//
// The header names no Cyclone type and no header generated into the build tree: the DDS side is
// in ClientCore (client_core.h, not installed), behind a pointer.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "client/client_error.h"
#include "client/client_types.h"
#include "client/reply_error.h"
#include "protocol/calculation.h"
#include "protocol/calculation_types.h"
#include "protocol/dds_error.h"
#include "protocol/requests.h"

namespace gc::client {

class ClientCore;

class Client {
 public:
  using Clock = std::chrono::steady_clock;

  /// Joins the domain and starts discovering instances. Throws protocol::DdsError.
  explicit Client(ClientOptions options);
  /// Fails the pending requests with ClientClosed and leaves the domain.
  ~Client();
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  template <protocol::Calculation kCalculation>
  using Request = typename protocol::CalculationTypes<kCalculation>::Request;
  template <protocol::Calculation kCalculation>
  using Result = typename protocol::CalculationTypes<kCalculation>::Result;
  template <protocol::Calculation kCalculation>
  using Callback = std::function<void(Outcome<Result<kCalculation>>)>;

  /// Sends `request` (waiting, like call_async, for a ready instance) and returns; `done` is
  /// called once with the result or the error: in Cyclone's receive thread as the reply arrives
  /// (no thread hand-off, as in ddsperf's listener mode), in this client's own thread for a
  /// timeout or ClientClosed, or before call_then returns when no instance was ready in time.
  /// It must not block or throw. It may send the next request of a calculation that has just
  /// been answered (an instance is ready, so that send does not wait for discovery).
  /// Defined in client.cc for the five calculations.
  template <protocol::Calculation kCalculation>
  void call_then(const Request<kCalculation>& request, Callback<kCalculation> done) {
    call_then<kCalculation>(request, std::move(done), Clock::now() + options().timeout);
  }
  /// call_then with a deadline of the caller's instead of now + ClientOptions::timeout: several
  /// calls that must all be answered by one time (a command's whole timeout) share it.
  template <protocol::Calculation kCalculation>
  void call_then(const Request<kCalculation>& request, Callback<kCalculation> done,
                 Clock::time_point deadline);

  /// Sends `request` and returns at once; the future holds the result or the error.
  template <protocol::Calculation kCalculation>
  std::future<Result<kCalculation>> call_async(const Request<kCalculation>& request) {
    return call_async<kCalculation>(request, Clock::now() + options().timeout);
  }
  /// call_async, failing with Timeout at `deadline`.
  template <protocol::Calculation kCalculation>
  std::future<Result<kCalculation>> call_async(const Request<kCalculation>& request,
                                               Clock::time_point deadline) {
    auto promise = std::make_shared<std::promise<Result<kCalculation>>>();
    std::future<Result<kCalculation>> future = promise->get_future();
    call_then<kCalculation>(request, [promise](Outcome<Result<kCalculation>> outcome) {
      if (outcome.error) {
        promise->set_exception(outcome.error);
      } else {
        promise->set_value(std::move(*outcome.result));
      }
    }, deadline);
    return future;
  }

  /// call_async(request).get(): the result, or throws the error. The caller spins on the
  /// future for up to ClientOptions::spin_before_sleep (none by default), then sleeps in it (a
  /// futex): a sleeping thread keeps the scheduler's wake-up preference, so on a busy host the
  /// reply wakes it ahead of CPU hogs.
  template <protocol::Calculation kCalculation>
  Result<kCalculation> call(const Request<kCalculation>& request) {
    return await(call_async<kCalculation>(request));
  }
  /// call, failing with Timeout at `deadline`.
  template <protocol::Calculation kCalculation>
  Result<kCalculation> call(const Request<kCalculation>& request, Clock::time_point deadline) {
    return await(call_async<kCalculation>(request, deadline));
  }

  /// Many cases of one calculation in few requests (docs/protocol.md, "Batches"): `cases`
  /// (each naming a coupling by its index in `couplings`, any number of either) go out in
  /// batches of at most protocol::kMaxBatchCases cases and kMaxBatchCouplings couplings, spread
  /// over the instances like single calls, at most kMaxBatchesInFlight batches of this client at
  /// once (all threads together: an instance keeps that many batch replies for resending).
  /// Returns one reply per case, in order: its result, or the status, field and message a single
  /// request of it gets (outcome_of() makes that the single call's Outcome); a case naming an
  /// index beyond `couplings` is refused in place (field "coupling"). Throws what call() throws
  /// (Timeout at `deadline`, ClientClosed, ServiceError) only when a whole batch fails.
  std::vector<protocol::BatchCaseReply> call_many(protocol::BatchCalculation calculation,
                                                  const std::vector<protocol::CouplingRef>& couplings,
                                                  const ContactOptions& options,
                                                  const std::vector<protocol::BatchCase>& cases,
                                                  Clock::time_point deadline);
  std::vector<protocol::BatchCaseReply> call_many(protocol::BatchCalculation calculation,
                                                  const std::vector<protocol::CouplingRef>& couplings,
                                                  const ContactOptions& options,
                                                  const std::vector<protocol::BatchCase>& cases) {
    return call_many(calculation, couplings, options, cases, Clock::now() + options_timeout());
  }

  /// Waits until some instance is ready to take `calculation`; false at `timeout`.
  bool wait_for_service(protocol::Calculation calculation, std::chrono::milliseconds timeout);
  /// Live instances known from the status topic.
  std::vector<InstanceInfo> instances() const;
  /// The definition of catalogue coupling `name` as a live instance announces it; nullopt when
  /// no known instance serves that name.
  std::optional<CouplingDefinition> catalogue_definition(const std::string& name) const;
  ClientCounters counters() const;
  std::uint64_t client_id() const;
  const ClientOptions& options() const;
  /// The Cyclone configuration this client joined its domain with, in words:
  /// "CYCLONEDDS_URI=<uri>", "<uri> (installed; CYCLONEDDS_URI unset)" or "Cyclone's default
  /// (CYCLONEDDS_URI unset)" (docs/deploy.md, "Which Cyclone configuration").
  const std::string& dds_configuration() const;

 private:
  struct BatchWindow;
  std::chrono::milliseconds options_timeout() const;

  /// future.get(), after spinning on it for up to ClientOptions::spin_before_sleep.
  template <typename T>
  T await(std::future<T> future) const {
    if (options().spin_before_sleep.count() > 0) {
      const Clock::time_point until = Clock::now() + options().spin_before_sleep;
      const bool real_time = real_time_thread();
      while (future.wait_for(Clock::duration::zero()) != std::future_status::ready &&
             Clock::now() < until) {
        spin_turn(real_time);
      }
    }
    return future.get();
  }
  /// Whether the calling thread runs under SCHED_FIFO or SCHED_RR.
  static bool real_time_thread();
  /// One turn of a spin. A real-time thread yields (sched_yield): a thread of its own priority
  /// queued on its core, such as this client's receive thread with the reply, would otherwise
  /// wait out the whole spin. A normal one tells the CPU it only waits (x86 `pause`, Arm
  /// `yield`): yielding would hand its core to a CPU hog for a whole time slice.
  static void spin_turn(bool real_time);

  std::unique_ptr<ClientCore> core_;
  std::unique_ptr<BatchWindow> batch_window_;  ///< kMaxBatchesInFlight slots
};

/// Batches of one client in flight at once, at most: an instance keeps the latest 16 batch replies
/// per client for resending (protocol::kBatchReplyHistoryDepth, docs/protocol.md "QoS").
inline constexpr int kMaxBatchesInFlight = 16;

/// A batch case's reply as the Outcome of a single call: the result, or the exception call()
/// throws for it (gc::InvalidInput naming the field, ...). `Result` is the batch's calculation's:
/// protocol::ContactAndMoments, InducedMoments, protocol::JamAngleResult or RestoringTorque.
template <typename Result>
Outcome<Result> outcome_of(protocol::BatchCaseReply reply) {
  Outcome<Result> outcome;
  if (reply.status == protocol::kCaseOk && std::holds_alternative<Result>(reply.value)) {
    outcome.result = std::move(std::get<Result>(reply.value));
    return outcome;
  }
  try {
    throw_reply_error(reply.status, reply.field.c_str(), reply.message.c_str());
  } catch (...) {
    outcome.error = std::current_exception();
  }
  return outcome;
}

}  // namespace gc::client
