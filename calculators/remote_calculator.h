// The Calculator that asks gearcoupling-service over DDS (gearcoupling --remote, the dashboard's
// query panel). Catalogue names go to the service by name (its catalogue); a coupling file is
// read here and sent inline. Results are the core's types, converted back from the replies, so
// every subcommand prints exactly what it prints in process. Any number of threads may call at
// once, each call waiting for its own replies: batch -j N keeps N rows in flight (2N requests: a
// row's tooth contact and moments go out together).
//
// Time: every call is answered within ClientOptions::timeout, discovery included, however many
// requests it makes (a load case is two, sharing one deadline); with a command deadline, no call
// waits past it either, so a command of several calls ends by its --timeout-s.
#pragma once

#include <chrono>
#include <map>
#include <mutex>
#include <optional>

#include "calculators/calculator.h"
#include "client/client.h"

namespace gc::calculators {

class RemoteCalculator final : public Calculator {
 public:
  using Clock = client::Client::Clock;

  /// Joins the domain (throws protocol::DdsError). With `timeout_is_deadline`, options.timeout
  /// counts from here and bounds every call together (a command's deadline: each call gets what
  /// is left, and fails with client::Timeout once nothing is); without, each call has
  /// options.timeout of its own, as a long-running process such as the dashboard wants.
  explicit RemoteCalculator(client::ClientOptions options, bool timeout_is_deadline = false);

  std::string coupling_name(std::string_view coupling) const override;
  ToothContact tooth_contact(std::string_view coupling, const OperatingPoint& point,
                             const ContactOptions& options) const override;
  LoadCase load_case(std::string_view coupling, const OperatingPoint& point,
                     const ContactOptions& options) const override;
  /// Batches of up to protocol::kMaxBatchCases cases (Client::call_many), one deadline for all.
  std::vector<LoadCaseOutcome> load_cases(const std::vector<LoadCaseInput>& cases,
                                          const ContactOptions& options) const override;
  JamAngleReport jam_angle(std::string_view coupling) const override;
  RestoringTorque restoring_torque(std::string_view coupling) const override;
  FrictionEstimate estimate_friction(std::string_view coupling,
                                     const FrictionMeasurement& measurement) const override;

 private:
  /// A catalogue name as is; a file read (once) into an inline definition.
  protocol::CouplingRef reference(std::string_view coupling) const;
  /// A call starting now ends by this: now + the timeout, or the command's deadline if sooner.
  Clock::time_point call_deadline() const;

  std::optional<Clock::time_point> command_deadline_;
  mutable client::Client client_;
  mutable std::mutex mutex_;  // guards files_
  mutable std::map<std::string, CouplingDefinition, std::less<>> files_;
};

}  // namespace gc::calculators
