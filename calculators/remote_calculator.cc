#include "calculators/remote_calculator.h"

#include <algorithm>

#include "calculators/coupling_reference.h"
#include "codec/coupling_file.h"

namespace gc::calculators {

using protocol::Calculation;

RemoteCalculator::RemoteCalculator(client::ClientOptions options, bool timeout_is_deadline)
    : client_(options) {
  // From here, not from before joining the domain: the first call then gets the whole timeout,
  // and its Timeout says so.
  if (timeout_is_deadline) command_deadline_ = Clock::now() + client_.options().timeout;
}

RemoteCalculator::Clock::time_point RemoteCalculator::call_deadline() const {
  const Clock::time_point own = Clock::now() + client_.options().timeout;
  return command_deadline_ ? std::min(own, *command_deadline_) : own;
}

protocol::CouplingRef RemoteCalculator::reference(std::string_view coupling) const {
  if (!is_file_reference(coupling)) return protocol::CatalogueName{std::string(coupling)};
  std::lock_guard lock(mutex_);
  auto found = files_.find(coupling);
  if (found == files_.end()) {
    found = files_.emplace(std::string(coupling),
                           codec::load_coupling_file(std::filesystem::path(coupling)))
                .first;
  }
  return found->second;
}

std::string RemoteCalculator::coupling_name(std::string_view coupling) const {
  const protocol::CouplingRef ref = reference(coupling);
  if (const auto* name = std::get_if<protocol::CatalogueName>(&ref)) return name->name;
  return std::get<CouplingDefinition>(ref).name;
}

ToothContact RemoteCalculator::tooth_contact(std::string_view coupling, const OperatingPoint& point,
                                             const ContactOptions& options) const {
  return client_.call<Calculation::kToothContact>({reference(coupling), point, options},
                                                 call_deadline());
}

LoadCase RemoteCalculator::load_case(std::string_view coupling, const OperatingPoint& point,
                                     const ContactOptions& options) const {
  const protocol::CouplingRef ref = reference(coupling);
  // Both requests in flight at once, one deadline for both: the second does not wait for a
  // service again after the first gave up.
  const Clock::time_point deadline = call_deadline();
  auto contact = client_.call_async<Calculation::kToothContact>({ref, point, options}, deadline);
  auto moments = client_.call_async<Calculation::kInducedMoments>({ref, point, options}, deadline);
  return {contact.get(), moments.get()};
}

std::vector<LoadCaseOutcome> RemoteCalculator::load_cases(const std::vector<LoadCaseInput>& cases,
                                                          const ContactOptions& options) const {
  std::vector<LoadCaseOutcome> out(cases.size());
  // Each distinct reference once: a coupling of the batch, or the error of every case naming it
  // (a file that does not read).
  std::map<std::string_view, std::uint32_t> index;
  std::vector<protocol::CouplingRef> couplings;
  std::vector<std::exception_ptr> reference_errors;
  std::vector<protocol::BatchCase> batch;
  std::vector<std::size_t> positions;
  batch.reserve(cases.size());
  positions.reserve(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    auto [it, added] = index.emplace(cases[i].coupling, static_cast<std::uint32_t>(couplings.size()));
    if (added) {
      reference_errors.emplace_back();
      try {
        couplings.push_back(reference(cases[i].coupling));
      } catch (...) {
        couplings.push_back(protocol::CatalogueName{});
        reference_errors.back() = std::current_exception();
      }
    }
    if (reference_errors[it->second]) {
      out[i].error = reference_errors[it->second];
      continue;
    }
    batch.push_back({it->second, cases[i].point});
    positions.push_back(i);
  }
  std::vector<protocol::BatchCaseReply> replies;
  try {
    replies = client_.call_many(protocol::BatchCalculation::kLoadCase, couplings, options, batch,
                                call_deadline());
  } catch (...) {  // a whole batch failed (Timeout, ...): the error of each of its cases
    const std::exception_ptr error = std::current_exception();
    for (std::size_t position : positions) out[position].error = error;
    return out;
  }
  for (std::size_t k = 0; k < replies.size(); ++k) {
    auto outcome = client::outcome_of<protocol::ContactAndMoments>(std::move(replies[k]));
    LoadCaseOutcome& o = out[positions[k]];
    if (outcome.error) {
      o.error = outcome.error;
    } else {
      o.result = LoadCase{protocol::contact_of(outcome.result->contact), outcome.result->moments};
    }
  }
  return out;
}

JamAngleReport RemoteCalculator::jam_angle(std::string_view coupling) const {
  const protocol::JamAngleResult result =
      client_.call<Calculation::kJamAngle>({reference(coupling)}, call_deadline());
  return {result.jam, result.crown_radius_m, result.crown_radius_derived};
}

RestoringTorque RemoteCalculator::restoring_torque(std::string_view coupling) const {
  return client_.call<Calculation::kRestoringTorque>({reference(coupling)}, call_deadline());
}

FrictionEstimate RemoteCalculator::estimate_friction(
    std::string_view coupling, const FrictionMeasurement& measurement) const {
  return client_.call<Calculation::kFrictionEstimate>({reference(coupling), measurement},
                                                     call_deadline());
}

}  // namespace gc::calculators
