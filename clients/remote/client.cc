#include "clients/remote/client.h"

#include <sched.h>

#include <stdexcept>
#include <string>

#include "clients/remote/client_core.h"

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

Client::Client(ClientOptions options)
    : core_(std::make_unique<ClientCore>(checked(std::move(options)))) {}

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
