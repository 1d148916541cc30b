// The dashboard's query panel: jam angle, tooth contact and induced moments of a coupling at an
// operating point, answered by gearcoupling-service through the CLI's RemoteCalculator, so the
// numbers are exactly `gearcoupling jam-angle|moments|contact --remote --json`'s. The only part
// of the dashboard that writes to DDS (requests).
#pragma once

#include <map>
#include <string>

#include "clients/cli/remote_calculator.h"

namespace gc::dashboard {

/// An HTTP answer: status code and a JSON body.
struct JsonAnswer {
  int status = 200;
  std::string body;
};

class QueryPanel {
 public:
  explicit QueryPanel(client::ClientOptions options) : calculator_(options) {}

  /// Parameters: coupling (a catalogue name), torque_nm [N m], misalignment_deg [deg],
  /// direction_deg [deg, default 0], friction_coefficient [-, default 0]. 200 with
  /// {"jam_angle": JamAngleResult, "moments": InducedMomentsResult, "contact":
  /// ToothContactResult} (idl/results.proto, as the CLI's --json); 400 naming the parameter when
  /// one is missing or not a number; 422 with the model's message (naming the field, its value
  /// and the allowed range) when the service refuses the input; 503 when no instance answers.
  JsonAnswer answer(const std::map<std::string, std::string>& parameters) const;

 private:
  cli::RemoteCalculator calculator_;
};

}  // namespace gc::dashboard
