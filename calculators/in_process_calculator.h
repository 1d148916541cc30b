// The Calculator that runs the core in this process. A coupling reference containing '/' or
// ending in ".textproto" is a file; anything else is a name in the catalogue directory, which
// is read on first use. Resolved couplings are kept, so a batch validates each one once.
#pragma once

#include <filesystem>
#include <map>
#include <mutex>
#include <optional>

#include "calculators/calculator.h"
#include "core/coupling_geometry.h"

namespace gc::calculators {

class InProcessCalculator final : public Calculator {
 public:
  explicit InProcessCalculator(std::filesystem::path catalog_dir);

  std::string coupling_name(std::string_view coupling) const override;
  ToothContact tooth_contact(std::string_view coupling, const OperatingPoint& point,
                             const ContactOptions& options) const override;
  LoadCase load_case(std::string_view coupling, const OperatingPoint& point,
                     const ContactOptions& options) const override;
  /// Each case as gc::induced_moments(coupling, point, options, contact): the contact without
  /// its table of teeth, which a batch does not keep (bit for bit load_case()'s members).
  std::vector<LoadCaseOutcome> load_cases(const std::vector<LoadCaseInput>& cases,
                                          const ContactOptions& options) const override;
  JamAngleReport jam_angle(std::string_view coupling) const override;
  RestoringTorque restoring_torque(std::string_view coupling) const override;
  FrictionEstimate estimate_friction(std::string_view coupling,
                                     const FrictionMeasurement& measurement) const override;

 private:
  /// The validated coupling for a reference; throws gc::InvalidInput naming "coupling".
  const CouplingGeometry& geometry(std::string_view coupling) const;

  // Couplings by name or file; std::map never moves its nodes, so references stay valid.
  using Couplings = std::map<std::string, const CouplingGeometry, std::less<>>;

  std::filesystem::path catalog_dir_;
  mutable std::mutex mutex_;  // guards the two maps below
  mutable std::optional<Couplings> catalog_;
  mutable Couplings files_;
};

}  // namespace gc::calculators
