#include "client/client.h"

#include <sched.h>

#include <deque>
#include <semaphore>
#include <stdexcept>
#include <string>

#include "client/client_core.h"
#include "core/model_error.h"
#include "protocol/reply_status.h"

namespace gc::client {

using protocol::Calculation;

namespace {

ClientOptions checked(ClientOptions options) {
  const auto spin_us = options.spin_before_sleep.count();
  if (spin_us < 0 || options.spin_before_sleep > kMaxSpinBeforeSleep) {
    throw std::invalid_argument("ClientOptions::spin_before_sleep: " + std::to_string(spin_us) +
                                " us (allowed: 0 to " +
                                std::to_string(kMaxSpinBeforeSleep.count()) + " us)");
  }
  return options;
}

}  // namespace

struct Client::BatchWindow {
  std::counting_semaphore<kMaxBatchesInFlight> slots{kMaxBatchesInFlight};
};

Client::Client(ClientOptions options)
    : core_(std::make_unique<ClientCore>(checked(std::move(options)))),
      batch_window_(std::make_unique<BatchWindow>()) {}

std::chrono::milliseconds Client::options_timeout() const { return options().timeout; }

namespace {

// One batch sent: its reply to come, and where its cases go in the caller's order.
struct SentBatch {
  std::future<protocol::BatchResult> reply;
  std::vector<std::size_t> positions;
};

}  // namespace

std::vector<protocol::BatchCaseReply> Client::call_many(
    protocol::BatchCalculation calculation, const std::vector<protocol::CouplingRef>& couplings,
    const ContactOptions& options, const std::vector<protocol::BatchCase>& cases,
    Clock::time_point deadline) {
  std::vector<protocol::BatchCaseReply> out(cases.size());
  std::deque<SentBatch> sent;  // this call's batches in flight, oldest first
  // Takes the oldest batch's reply, frees its slot. On an error the remaining batches' slots are
  // freed as their replies are abandoned (the futures are simply dropped).
  auto collect_oldest = [&] {
    SentBatch batch = std::move(sent.front());
    sent.pop_front();
    struct Release {
      BatchWindow& window;
      ~Release() { window.slots.release(); }
    } release{*batch_window_};
    protocol::BatchResult result = batch.reply.get();
    if (result.cases.size() != batch.positions.size()) {
      throw protocol::ServiceError({gearcoupling_STATUS_INTERNAL_ERROR, "",
                                    "a batch reply carried " + std::to_string(result.cases.size()) +
                                        " cases for " + std::to_string(batch.positions.size()) +
                                        " sent"});
    }
    for (std::size_t k = 0; k < result.cases.size(); ++k) {
      out[batch.positions[k]] = std::move(result.cases[k]);
    }
  };
  struct DropRemaining {  // frees the slots of batches not collected (an exception)
    std::deque<SentBatch>& sent;
    BatchWindow& window;
    ~DropRemaining() {
      for (std::size_t i = 0; i < sent.size(); ++i) window.slots.release();
    }
  } drop_remaining{sent, *batch_window_};

  // Where each of `couplings` sits in the batch being built (-1: not in it yet).
  std::vector<std::int64_t> local(couplings.size(), -1);
  std::size_t i = 0;
  while (i < cases.size()) {
    protocol::BatchRequest request{calculation, {}, options, {}};
    std::vector<std::size_t> positions;
    std::vector<std::uint32_t> used;  // couplings of this batch, to reset `local` after
    while (i < cases.size() && request.cases.size() < protocol::kMaxBatchCases) {
      const protocol::BatchCase& c = cases[i];
      if (c.coupling >= couplings.size()) {  // answered here, as the service would
        out[i] = {gearcoupling_STATUS_INVALID_INPUT, "coupling",
                  InvalidInput("coupling", static_cast<double>(c.coupling),
                               couplings.empty()
                                   ? std::string("none (no couplings given)")
                                   : "[0, " + std::to_string(couplings.size() - 1) +
                                         "] (an index into the couplings)")
                      .what(),
                  std::monostate{}};
        ++i;
        continue;
      }
      if (local[c.coupling] < 0) {
        if (request.couplings.size() == protocol::kMaxBatchCouplings) break;
        local[c.coupling] = static_cast<std::int64_t>(request.couplings.size());
        request.couplings.push_back(couplings[c.coupling]);
        used.push_back(c.coupling);
      }
      request.cases.push_back({static_cast<std::uint32_t>(local[c.coupling]), c.operating_point});
      positions.push_back(i++);
    }
    for (std::uint32_t c : used) local[c] = -1;
    if (request.cases.empty()) continue;
    // A slot of the client's window; while none is free, this call's own oldest batch is
    // collected first (so no thread waits holding slots another needs).
    while (!batch_window_->slots.try_acquire()) {
      if (!sent.empty()) {
        collect_oldest();
      } else if (!batch_window_->slots.try_acquire_until(deadline)) {
        throw Timeout("no room for a batch in this client's window of " +
                      std::to_string(kMaxBatchesInFlight) + " batches before the deadline");
      } else {
        break;
      }
    }
    sent.push_back({call_async<protocol::Calculation::kBatch>(request, deadline),
                    std::move(positions)});
  }
  while (!sent.empty()) collect_oldest();
  return out;
}

Client::~Client() = default;

template <Calculation kCalculation>
void Client::call_then(const Request<kCalculation>& request, Callback<kCalculation> done,
                       Clock::time_point deadline) {
  core_->call_then<kCalculation>(request, std::move(done), deadline);
}

template void Client::call_then<Calculation::kToothContact>(
    const Request<Calculation::kToothContact>&, Callback<Calculation::kToothContact>, Clock::time_point);
template void Client::call_then<Calculation::kJamAngle>(const Request<Calculation::kJamAngle>&,
                                                        Callback<Calculation::kJamAngle>, Clock::time_point);
template void Client::call_then<Calculation::kInducedMoments>(
    const Request<Calculation::kInducedMoments>&, Callback<Calculation::kInducedMoments>, Clock::time_point);
template void Client::call_then<Calculation::kRestoringTorque>(
    const Request<Calculation::kRestoringTorque>&, Callback<Calculation::kRestoringTorque>, Clock::time_point);
template void Client::call_then<Calculation::kFrictionEstimate>(
    const Request<Calculation::kFrictionEstimate>&, Callback<Calculation::kFrictionEstimate>, Clock::time_point);
template void Client::call_then<Calculation::kBatch>(const Request<Calculation::kBatch>&,
                                                     Callback<Calculation::kBatch>, Clock::time_point);

bool Client::real_time_thread() {
  const int policy = sched_getscheduler(0);
  return policy == SCHED_FIFO || policy == SCHED_RR;
}

void Client::spin_turn(bool real_time) {
  if (real_time) {
    sched_yield();
    return;
  }
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__) || defined(__arm__)
  asm volatile("yield");
#endif
}

bool Client::wait_for_service(Calculation calculation, std::chrono::milliseconds timeout) {
  return core_->wait_for_service(calculation, timeout);
}

std::vector<InstanceInfo> Client::instances() const { return core_->instances(); }

std::optional<CouplingDefinition> Client::catalogue_definition(const std::string& name) const {
  return core_->catalogue_definition(name);
}

ClientCounters Client::counters() const { return core_->counters(); }

std::uint64_t Client::client_id() const { return core_->client_id(); }

const ClientOptions& Client::options() const { return core_->options(); }

const std::string& Client::dds_configuration() const { return core_->dds_configuration(); }

}  // namespace gc::client
