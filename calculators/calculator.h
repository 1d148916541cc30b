// What the subcommands ask of the model, behind one interface: the in-process implementation
// (in_process_calculator.h) calls the core directly; a remote one can answer over DDS without
// the subcommands changing. Couplings are named by reference: a catalogue name or a file.
#pragma once

#include <exception>
#include <optional>
#include <string>
#include <vector>
#include <string_view>

#include "analysis/load_case.h"
#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/jam_angle.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"

namespace gc::calculators {

using analysis::LoadCase;

/// The jam angle with the crown radius it was computed for.
struct JamAngleReport {
  JamAngle jam;
  double crown_radius_m = 0.0;       ///< R_F [m]
  bool crown_radius_derived = false; ///< R_F came from the lead modification
};

/// One load case of many (Calculator::load_cases): a coupling reference and an operating point.
struct LoadCaseInput {
  std::string coupling;
  OperatingPoint point;
};

/// One case's answer: the result, or the error load_case() would have thrown for it.
struct LoadCaseOutcome {
  std::optional<LoadCase> result;
  std::exception_ptr error;
};

/// Every method may be called from any number of threads at once. Errors are gc::ModelError
/// (gc::InvalidInput naming the field for bad input, gc::NotConverged).
class Calculator {
 public:
  virtual ~Calculator() = default;

  /// The coupling's own name (from its definition) for a reference.
  virtual std::string coupling_name(std::string_view coupling) const = 0;
  /// Eqs 5-22.
  virtual ToothContact tooth_contact(std::string_view coupling, const OperatingPoint& point,
                                     const ContactOptions& options) const = 0;
  /// Eqs 5-48.
  virtual LoadCase load_case(std::string_view coupling, const OperatingPoint& point,
                             const ContactOptions& options) const = 0;
  /// load_case() for every case, in order, each case's error in place (never thrown). Every
  /// result's contact carries at least protocol::ContactSummary's members (what a batch CSV row
  /// reads; over DDS a batch carries no more: docs/protocol.md, "Batches"), and no teeth. In
  /// process: one case after another on the calling thread; RemoteCalculator: in batches.
  virtual std::vector<LoadCaseOutcome> load_cases(const std::vector<LoadCaseInput>& cases,
                                                  const ContactOptions& options) const;
  /// Eqs 23-35.
  virtual JamAngleReport jam_angle(std::string_view coupling) const = 0;
  /// Eqs 49-53.
  virtual RestoringTorque restoring_torque(std::string_view coupling) const = 0;
  /// Eqs 1-4.
  virtual FrictionEstimate estimate_friction(std::string_view coupling,
                                             const FrictionMeasurement& measurement) const = 0;
};

}  // namespace gc::calculators
