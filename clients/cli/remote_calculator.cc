#include "clients/cli/remote_calculator.h"

#include "clients/cli/coupling_reference.h"
#include "codec/coupling_file.h"

namespace gc::cli {

using protocol::Calculation;

RemoteCalculator::RemoteCalculator(client::ClientOptions options) : client_(options) {}

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
  return client_.call<Calculation::kToothContact>({reference(coupling), point, options});
}

LoadCase RemoteCalculator::load_case(std::string_view coupling, const OperatingPoint& point,
                                     const ContactOptions& options) const {
  const protocol::CouplingRef ref = reference(coupling);
  // Both requests in flight at once; the service computes the moments from the same contact.
  auto contact = client_.call_async<Calculation::kToothContact>({ref, point, options});
  auto moments = client_.call_async<Calculation::kInducedMoments>({ref, point, options});
  return {contact.get(), moments.get()};
}

JamAngleReport RemoteCalculator::jam_angle(std::string_view coupling) const {
  const protocol::JamAngleResult result =
      client_.call<Calculation::kJamAngle>({reference(coupling)});
  return {result.jam, result.crown_radius_m, result.crown_radius_derived};
}

RestoringTorque RemoteCalculator::restoring_torque(std::string_view coupling) const {
  return client_.call<Calculation::kRestoringTorque>({reference(coupling)});
}

FrictionEstimate RemoteCalculator::estimate_friction(
    std::string_view coupling, const FrictionMeasurement& measurement) const {
  return client_.call<Calculation::kFrictionEstimate>({reference(coupling), measurement});
}

}  // namespace gc::cli
