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
  kLoadCase,         ///< tooth contact without its teeth, and the induced moments (eqs 5-48)
  kInducedMoments,   ///< eqs 36-48
  kJamAngle,         ///< eqs 23-35: reads only the coupling
  kRestoringTorque,  ///< eqs 49-53: reads only the coupling
};

/// Tooth contact and the moments computed from it: one row of `gearcoupling batch`. Over the
/// wire `contact.teeth` is empty; every other member is the single request's, bit for bit.
struct ContactAndMoments {
  ToothContact contact;
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
