// The dashboard's query panel: jam angle, tooth contact and induced moments of a coupling at an
// operating point, answered by gearcoupling-service through gc_calculators' RemoteCalculator, so the
// numbers are exactly `gearcoupling jam-angle|moments|contact --remote --json`'s. The only part
// of the dashboard that writes to DDS (requests).
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "calculators/remote_calculator.h"

namespace gc::dashboard {

/// An HTTP answer: status code and a JSON body.
struct JsonAnswer {
  int status = 200;
  std::string body;
};

/// Queries answered so far, by outcome (/metrics: gearcoupling_dashboard_queries_total).
struct QueryCounts {
  std::uint64_t answered = 0;  ///< 200
  std::uint64_t refused = 0;   ///< 400, 422: the user's input, not a failure
  std::uint64_t failed = 0;    ///< 403, 503: the panel may not ask, or no instance answered
};

class QueryPanel {
 public:
  /// Joins the domain as a client. Under DDS Security, an identity that may not ask the service
  /// (a dashboard-* identity, or a console's without its prefix) does not stop the dashboard:
  /// the panel answers every query with 403 and why (refusal_message). Throws
  /// protocol::DdsError for any other failure.
  explicit QueryPanel(client::ClientOptions options);

  /// Parameters: coupling (a catalogue name), torque_nm [N m], misalignment_deg [deg],
  /// direction_deg [deg, default 0], friction_coefficient [-, default 0]. 200 with
  /// {"jam_angle": JamAngleResult, "moments": InducedMomentsResult, "contact":
  /// ToothContactResult} (idl/results.proto, as the CLI's --json); 400 naming the parameter when
  /// one is missing or not a number; 422 with the model's message (naming the field, its value
  /// and the allowed range) when the service refuses the input; 403 when DDS Security does not
  /// let this identity ask (refusal_message); 503 when no instance answers. An error body is
  /// {"error": text, "parameter": the parameter it concerns, when known}. Counted (counts()).
  JsonAnswer answer(const std::map<std::string, std::string>& parameters) const;
  QueryCounts counts() const;

  /// The 403 text: this identity may not send requests or read replies, why (its grants), what
  /// to do (run under a console identity with its --client-id-prefix), and DDS's own words.
  static std::string refusal_message(const std::string& dds_error);

 private:
  JsonAnswer answer_uncounted(const std::map<std::string, std::string>& parameters) const;
  JsonAnswer compute(const std::map<std::string, std::string>& parameters) const;

  mutable std::atomic<std::uint64_t> answered_{0}, refused_{0}, failed_{0};

  std::unique_ptr<calculators::RemoteCalculator> calculator_;  ///< null when security refused it
  std::string refusal_;                                ///< why, when it did
};

}  // namespace gc::dashboard
