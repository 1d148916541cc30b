// libFuzzer target: a batch request (idl/gearcoupling.idl "Batches") from its IDL C type to the
// reply, the path Service::take_requests and Service::answer take for one: protocol::from_wire
// (the bounds on cases and couplings, the calculation), service::compute_batch (each coupling
// resolved once, each case answered in place) and the result's protocol::to_wire into the reply.
//
// Input (docs/fuzzing.md, "batch_request_fuzzer's input"): a byte for the calculation (modulo
// the four BatchCalculation values: Cyclone drops a sample with another), a byte for the number
// of couplings (0 .. 65: one past either bound), each coupling as wire_request_fuzzer reads one,
// the contact options, a u16 for the number of cases (0 .. 4097), then per case a u32 coupling
// index (any: out of range is a case's error) and the operating point. Past the input's end every
// value is zero, so a short input can still name 4097 cases.
//
// Checks: from_wire throws only InvalidInput naming a field; every case is answered, in order,
// with a result (checked as the single request's) or an error that names a client's fault
// (never STATUS_INTERNAL_ERROR) and, for invalid input, its field; texts within
// BATCH_MAX_CASE_TEXT_BYTES; the reply converts to the wire and back with the same statuses.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <variant>
#include <vector>

#include "fuzz/fuzz_checks.h"
#include "fuzz/wire_bytes.h"
#include "protocol/batch_types.h"
#include "protocol/calculation_traits.h"
#include "protocol/samples.h"
#include "protocol/wire_requests.h"
#include "protocol/wire_results.h"
#include "service/batch.h"

namespace {

using namespace gc::fuzz;
using gc::protocol::Calculation;

struct WireBatch {
  gearcoupling_BatchRequest request{};
  std::deque<WireStorage> storage;  // what the couplings' pointers point into
  std::vector<gearcoupling_CouplingRef> couplings;
  std::vector<gearcoupling_BatchCase> cases;
};

void read_batch(Bytes& in, WireBatch& batch) {
  gearcoupling_BatchRequest& r = batch.request;
  r.calculation = static_cast<gearcoupling_BatchCalculation>(in.read<std::uint8_t>() % 4);
  const std::size_t couplings = in.read<std::uint8_t>() % (gc::protocol::kMaxBatchCouplings + 2);
  batch.couplings.resize(couplings);
  for (gearcoupling_CouplingRef& ref : batch.couplings) read_coupling(in, batch.storage.emplace_back(), ref);
  r.options = read_options(in);
  const std::size_t cases = in.read<std::uint16_t>() % (gc::protocol::kMaxBatchCases + 2);
  batch.cases.resize(cases);
  for (gearcoupling_BatchCase& c : batch.cases) {
    c.coupling = in.read<std::uint32_t>();
    c.operating_point = read_operating_point(in);
  }
  r.couplings._buffer = batch.couplings.data();
  r.couplings._length = r.couplings._maximum = static_cast<std::uint32_t>(couplings);
  r.cases._buffer = batch.cases.data();
  r.cases._length = r.cases._maximum = static_cast<std::uint32_t>(cases);
}

void check_case(const gc::protocol::BatchCaseReply& reply) {
  if (reply.field.size() > gc::protocol::kMaxBatchCaseTextBytes ||
      reply.message.size() > gc::protocol::kMaxBatchCaseTextBytes) {
    fail("a case's text beyond BATCH_MAX_CASE_TEXT_BYTES");
  }
  if (reply.status != gc::protocol::kCaseOk) {
    check_error({static_cast<gearcoupling_ReplyStatus>(reply.status), reply.field, reply.message});
    if (!std::holds_alternative<std::monostate>(reply.value)) fail("an error case with a result");
    return;
  }
  std::visit([](const auto& value) {
    using Value = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<Value, std::monostate>) {
      fail("a case answered OK without a result");
    } else if constexpr (std::is_same_v<Value, gc::protocol::ContactAndMoments>) {
      check(value.moments);
    } else if constexpr (std::is_same_v<Value, gc::protocol::JamAngleResult>) {
      check(value.jam);
    } else {
      check(value);
    }
  }, reply.value);
}

// What Service::answer does with a batch that converted.
void answer(const gc::protocol::BatchRequest& request) {
  using T = gc::protocol::CalculationTraits<Calculation::kBatch>;
  const gc::protocol::BatchResult result = gc::service::compute_batch(
      catalogue(), request, {}, [] { return std::make_exception_ptr(gc::Cancelled("deadline")); });
  if (result.cases.size() != request.cases.size()) fail("not one answer per case");
  for (const gc::protocol::BatchCaseReply& reply : result.cases) check_case(reply);
  gc::protocol::OwnedSample<T::WireReply> reply(T::reply_type());
  gc::protocol::to_wire(result, reply.get().result);
  const gc::protocol::BatchResult back = gc::protocol::from_wire(reply.get().result);
  if (back.cases.size() != result.cases.size()) fail("the wire lost cases");
  for (std::size_t i = 0; i < back.cases.size(); ++i) {
    if (back.cases[i].status != result.cases[i].status) fail("the wire changed a case's status");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  WireBatch batch;
  read_batch(in, batch);
  std::optional<gc::protocol::BatchRequest> request;
  expect_result_or<gc::InvalidInput>([&] { request = gc::protocol::from_wire(batch.request); });
  if (request) answer(*request);
  return 0;
}
