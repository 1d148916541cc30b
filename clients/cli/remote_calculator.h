// The Calculator that asks gearcoupling-service over DDS (gearcoupling --remote). Catalogue
// names go to the service by name (its catalogue); a coupling file is read here and sent inline.
// Results are the core's types, converted back from the replies, so every subcommand prints
// exactly what it prints in process. Any number of threads may call at once, each call waiting
// for its own replies: batch -j N keeps N rows in flight (2N requests: a row's tooth contact and
// moments go out together).
#pragma once

#include <map>
#include <mutex>

#include "clients/cli/calculator.h"
#include "clients/remote/client.h"

namespace gc::cli {

class RemoteCalculator final : public Calculator {
 public:
  explicit RemoteCalculator(client::ClientOptions options);

  std::string coupling_name(std::string_view coupling) const override;
  ToothContact tooth_contact(std::string_view coupling, const OperatingPoint& point,
                             const ContactOptions& options) const override;
  LoadCase load_case(std::string_view coupling, const OperatingPoint& point,
                     const ContactOptions& options) const override;
  JamAngleReport jam_angle(std::string_view coupling) const override;
  RestoringTorque restoring_torque(std::string_view coupling) const override;
  FrictionEstimate estimate_friction(std::string_view coupling,
                                     const FrictionMeasurement& measurement) const override;

 private:
  /// A catalogue name as is; a file read (once) into an inline definition.
  protocol::CouplingRef reference(std::string_view coupling) const;

  mutable client::Client client_;
  mutable std::mutex mutex_;  // guards files_
  mutable std::map<std::string, CouplingDefinition, std::less<>> files_;
};

}  // namespace gc::cli
