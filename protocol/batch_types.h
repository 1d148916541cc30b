// A batch: many load cases of one calculation in one request, answered in one reply
// (idl/gearcoupling.idl "Batches", docs/protocol.md "Batches"), as core value types. Each case is
// answered in place with what a single request of it would get: its result, or its error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "core/induced_moments.h"
#include "core/operating_point.h"
#include "core/restoring_torque.h"
#include "core/stress.h"
#include "core/tooth_contact.h"
#include "protocol/jam_angle_result.h"
#include "protocol/requests.h"

namespace gc::protocol {

/// The IDL's BATCH_MAX_CASES: a batch with more is refused whole (field "cases"). 4096 default
/// load cases cost the service about 5 ms and 0.5 MB of reply; the per-calculation deadline bounds
/// a batch of costly cases (10,000 teeth) as it bounds one costly request.
inline constexpr std::size_t kMaxBatchCases = 4096;
/// The IDL's BATCH_MAX_COUPLINGS: couplings one batch may name (field "couplings").
inline constexpr std::size_t kMaxBatchCouplings = 64;
/// The IDL's BATCH_MAX_CASE_TEXT_BYTES: a case's field and message are cut to this (echo_text),
/// so 4096 failed cases make at most about 2 MB of reply.
inline constexpr std::size_t kMaxBatchCaseTextBytes = 256;

/// What each case of a batch computes (the IDL's BatchCalculation).
enum class BatchCalculation {
  kLoadCase,         ///< the tooth contact's summary and the induced moments (eqs 5-48)
  kInducedMoments,   ///< eqs 36-48
  kJamAngle,         ///< eqs 23-35: reads only the coupling
  kRestoringTorque,  ///< eqs 49-53: reads only the coupling
};

/// What one row of `gearcoupling batch` takes of a tooth contact (eqs 5-22), member for member
/// ToothContact's of the same names: the load sharing, the teeth in contact, the most loaded
/// tooth and its stress. A batch carries this rather than the whole contact: a third of the
/// members, and so about a third of the serialising and checking per case at either end.
struct ContactSummary {
  LoadSharing load_sharing;
  int teeth_in_contact = 0;
  int max_load_tooth = 0;
  double max_tooth_load_n = 0.0;
  bool edge_loaded = false;
  ToothStress max_stress;
};

inline ContactSummary summary_of(const ToothContact& contact) {
  return {contact.load_sharing,     contact.teeth_in_contact, contact.max_load_tooth,
          contact.max_tooth_load_n, contact.edge_loaded,      contact.max_stress};
}

/// A ToothContact with the summary's members, the others zero and no teeth: what a batch CSV
/// row or a CaseTable of load cases reads.
inline ToothContact contact_of(const ContactSummary& summary) {
  ToothContact contact;
  contact.load_sharing = summary.load_sharing;
  contact.teeth_in_contact = summary.teeth_in_contact;
  contact.max_load_tooth = summary.max_load_tooth;
  contact.max_tooth_load_n = summary.max_tooth_load_n;
  contact.edge_loaded = summary.edge_loaded;
  contact.max_stress = summary.max_stress;
  return contact;
}

/// Tooth contact and the moments computed from it: one row of `gearcoupling batch`, each member
/// the single requests' (ToothContactRequest, InducedMomentsRequest) bit for bit.
struct ContactAndMoments {
  ContactSummary contact;
  InducedMoments moments;
};

struct BatchCase {
  std::uint32_t coupling = 0;  ///< index into BatchRequest::couplings
  OperatingPoint operating_point;
};

struct BatchRequest {
  BatchCalculation calculation = BatchCalculation::kLoadCase;
  std::vector<CouplingRef> couplings;  ///< 1 .. kMaxBatchCouplings
  ContactOptions options;              ///< for every case
  std::vector<BatchCase> cases;        ///< 0 .. kMaxBatchCases
};

/// A case's status: the IDL's ReplyStatus, value for value (0 is STATUS_OK).
using CaseStatus = int;
inline constexpr CaseStatus kCaseOk = 0;

/// One case's answer. `value` holds the batch's calculation's result when status == kCaseOk,
/// std::monostate otherwise; field and message are then the single request's error (cut to
/// kMaxBatchCaseTextBytes).
struct BatchCaseReply {
  CaseStatus status = kCaseOk;
  std::string field;
  std::string message;
  std::variant<std::monostate, ContactAndMoments, InducedMoments, JamAngleResult, RestoringTorque>
      value;
};

struct BatchResult {
  BatchCalculation calculation = BatchCalculation::kLoadCase;
  std::vector<BatchCaseReply> cases;  ///< in the request's order
};

}  // namespace gc::protocol
