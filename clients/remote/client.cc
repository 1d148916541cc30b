#include "clients/remote/client.h"

#include "clients/remote/client_core.h"

namespace gc::client {

using protocol::Calculation;

Client::Client(ClientOptions options) : core_(std::make_unique<ClientCore>(std::move(options))) {}

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
