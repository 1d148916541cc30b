// Batches between core value types (protocol/batch_types.h) and the IDL's C types.
#include <cstring>

#include <fmt/format.h>

#include "core/model_error.h"
#include "protocol/field_copy.h"
#include "protocol/reply_status.h"
#include "protocol/wire_inputs.h"
#include "protocol/wire_requests.h"
#include "protocol/wire_results.h"

namespace gc::protocol {
namespace {

static_assert(kMaxBatchCases == gearcoupling_BATCH_MAX_CASES);
static_assert(kMaxBatchCouplings == gearcoupling_BATCH_MAX_COUPLINGS);
static_assert(kMaxBatchCaseTextBytes == gearcoupling_BATCH_MAX_CASE_TEXT_BYTES);
static_assert(gearcoupling_STATUS_OK == kCaseOk);

// A sequence of `count` elements; `zeroed` for elements the caller does not set member by member.
template <typename Element, typename Sequence>
void allocate(Sequence& sequence, std::size_t count, bool zeroed) {
  sequence._buffer =
      count == 0 ? nullptr : static_cast<Element*>(dds_alloc(count * sizeof(Element)));
  if (count > 0 && zeroed) std::memset(sequence._buffer, 0, count * sizeof(Element));
  sequence._length = sequence._maximum = static_cast<std::uint32_t>(count);
  sequence._release = true;
}

gearcoupling_BatchCalculation calculation_to_wire(BatchCalculation calculation) {
  switch (calculation) {
    case BatchCalculation::kLoadCase: return gearcoupling_BATCH_LOAD_CASE;
    case BatchCalculation::kInducedMoments: return gearcoupling_BATCH_INDUCED_MOMENTS;
    case BatchCalculation::kJamAngle: return gearcoupling_BATCH_JAM_ANGLE;
    case BatchCalculation::kRestoringTorque: return gearcoupling_BATCH_RESTORING_TORQUE;
  }
  return gearcoupling_BATCH_LOAD_CASE;
}

BatchCalculation calculation_from_wire(gearcoupling_BatchCalculation calculation) {
  switch (calculation) {
    case gearcoupling_BATCH_LOAD_CASE: return BatchCalculation::kLoadCase;
    case gearcoupling_BATCH_INDUCED_MOMENTS: return BatchCalculation::kInducedMoments;
    case gearcoupling_BATCH_JAM_ANGLE: return BatchCalculation::kJamAngle;
    case gearcoupling_BATCH_RESTORING_TORQUE: return BatchCalculation::kRestoringTorque;
  }
  throw InvalidInput("calculation",
                     fmt::format("{} is not a BatchCalculation (allowed 0 to 3)",
                                 static_cast<long>(calculation)));
}

void refuse_count(const char* field, std::size_t count, std::size_t lo, std::size_t hi,
                  const char* limit) {
  if (count >= lo && count <= hi) return;
  throw InvalidInput(field, fmt::format("{} in one batch is out of range: allowed {} to {} ({}); "
                                        "send the rest in another batch",
                                        count, lo, hi, limit));
}

// A load case's contact, one field list for both directions (as wire_results.cc).
template <typename Core, typename Wire, typename Copy>
void contact_fields(Core& core, Wire& wire, Copy copy) {
  copy(core.load_sharing.q, wire.load_sharing.q);
  copy(core.load_sharing.ze_over_zo, wire.load_sharing.ze_over_zo);
  copy(core.load_sharing.iterations, wire.load_sharing.iterations);
  copy(core.teeth_in_contact, wire.teeth_in_contact);
  copy(core.max_load_tooth, wire.max_load_tooth);
  copy(core.max_tooth_load_n, wire.max_tooth_load_n);
  copy(core.edge_loaded, wire.edge_loaded);
  copy(core.max_stress.contact_stress_pa, wire.max_stress.contact_stress_pa);
  copy(core.max_stress.contact_half_width_m, wire.max_stress.contact_half_width_m);
  copy(core.max_stress.bending_stress_pa, wire.max_stress.bending_stress_pa);
  copy(core.max_stress.contact_safety_factor, wire.max_stress.contact_safety_factor);
  copy(core.max_stress.bending_safety_factor, wire.max_stress.bending_safety_factor);
}

void case_to_wire(const BatchCaseReply& in, gearcoupling_BatchCaseReply& out,
                  gearcoupling_BatchCalculation calculation) {
  out.status = static_cast<gearcoupling_ReplyStatus>(in.status);
  // A null string is written as "" (Cyclone's dds_stream_write_string) and freed as nothing:
  // a good case costs no allocation for its empty field and message. (Bounded strings,
  // string<256>, cost the receiver no allocation either, but made the sample 520 bytes larger
  // per case, and the service, which maps each reply of over 128 kB afresh (service/main.cc),
  // more in page faults than the client saved: 1.92 against 1.80 s of CPU per 200,000 cases.)
  out.field = in.field.empty() ? nullptr : wire_string(echo_text(in.field, kMaxBatchCaseTextBytes));
  out.message =
      in.message.empty() ? nullptr : wire_string(echo_text(in.message, kMaxBatchCaseTextBytes));
  out.result._d = calculation;
  if (std::holds_alternative<std::monostate>(in.value)) {
    std::memset(&out.result._u, 0, sizeof(out.result._u));
  } else if (const auto* value = std::get_if<ContactAndMoments>(&in.value)) {
    contact_fields(value->contact, out.result._u.load_case.contact, kToWire);
    to_wire(value->moments, out.result._u.load_case.moments);
  } else if (const auto* moments = std::get_if<InducedMoments>(&in.value)) {
    to_wire(*moments, out.result._u.induced_moments);
  } else if (const auto* jam = std::get_if<JamAngleResult>(&in.value)) {
    to_wire(*jam, out.result._u.jam_angle);
  } else if (const auto* restoring = std::get_if<RestoringTorque>(&in.value)) {
    to_wire(*restoring, out.result._u.restoring_torque);
  }
}

BatchCaseReply case_from_wire(const gearcoupling_BatchCaseReply& in) {
  BatchCaseReply out;
  out.status = static_cast<CaseStatus>(in.status);
  out.field = in.field != nullptr ? in.field : "";
  out.message = in.message != nullptr ? in.message : "";
  if (out.status != kCaseOk) return out;
  switch (in.result._d) {
    case gearcoupling_BATCH_LOAD_CASE:
      out.value = ContactAndMoments{{}, from_wire(in.result._u.load_case.moments)};
      contact_fields(std::get<ContactAndMoments>(out.value).contact, in.result._u.load_case.contact,
                     kFromWire);
      break;
    case gearcoupling_BATCH_INDUCED_MOMENTS:
      out.value = from_wire(in.result._u.induced_moments);
      break;
    case gearcoupling_BATCH_JAM_ANGLE: out.value = from_wire(in.result._u.jam_angle); break;
    case gearcoupling_BATCH_RESTORING_TORQUE:
      out.value = from_wire(in.result._u.restoring_torque);
      break;
  }
  return out;
}

}  // namespace

void to_wire(const BatchRequest& in, gearcoupling_BatchRequest& out) {
  out.calculation = calculation_to_wire(in.calculation);
  allocate<gearcoupling_CouplingRef>(out.couplings, in.couplings.size(), true);
  for (std::size_t i = 0; i < in.couplings.size(); ++i) {
    to_wire(in.couplings[i], out.couplings._buffer[i]);
  }
  to_wire(in.options, out.options);
  allocate<gearcoupling_BatchCase>(out.cases, in.cases.size(), false);
  for (std::size_t i = 0; i < in.cases.size(); ++i) {
    out.cases._buffer[i].coupling = in.cases[i].coupling;
    to_wire(in.cases[i].operating_point, out.cases._buffer[i].operating_point);
  }
}

BatchRequest from_wire(const gearcoupling_BatchRequest& in) {
  // The sizes first: a refused batch costs no conversion.
  refuse_count("cases", in.cases._length, 0, kMaxBatchCases, "BATCH_MAX_CASES");
  refuse_count("couplings", in.couplings._length, 1, kMaxBatchCouplings, "BATCH_MAX_COUPLINGS");
  BatchRequest out;
  out.calculation = calculation_from_wire(in.calculation);
  out.couplings.reserve(in.couplings._length);
  for (std::uint32_t i = 0; i < in.couplings._length; ++i) {
    try {
      out.couplings.push_back(from_wire(in.couplings._buffer[i]));
    } catch (const InvalidInput& error) {
      throw InvalidInput(fmt::format("couplings[{}]", i), error.what());
    }
  }
  out.options = from_wire(in.options);
  out.cases.resize(in.cases._length);
  for (std::uint32_t i = 0; i < in.cases._length; ++i) {
    out.cases[i].coupling = in.cases._buffer[i].coupling;
    out.cases[i].operating_point = from_wire(in.cases._buffer[i].operating_point);
  }
  return out;
}

void to_wire(const BatchResult& in, gearcoupling_BatchResult& out) {
  allocate<gearcoupling_BatchCaseReply>(out.cases, in.cases.size(), false);
  // Every case's union carries the batch's calculation; a failed case's result stays zero.
  const gearcoupling_BatchCalculation calculation = calculation_to_wire(in.calculation);
  for (std::size_t i = 0; i < in.cases.size(); ++i) {
    case_to_wire(in.cases[i], out.cases._buffer[i], calculation);
  }
}

BatchResult from_wire(const gearcoupling_BatchResult& in) {
  BatchResult out;
  if (in.cases._length > 0) out.calculation = calculation_from_wire(in.cases._buffer[0].result._d);
  out.cases.reserve(in.cases._length);
  for (std::uint32_t i = 0; i < in.cases._length; ++i) out.cases.push_back(case_from_wire(in.cases._buffer[i]));
  return out;
}

}  // namespace gc::protocol
