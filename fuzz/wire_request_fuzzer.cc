// libFuzzer target: every request of the DDS interface from its IDL C type to a result, the path
// Service::take_requests and Service::answer take (service/service.cc): protocol::from_wire,
// Catalogue::resolve (an inline coupling is validated there), service::compute, and the
// result's protocol::to_wire into the reply.
//
// The request is built member by member from the input (layout in docs/fuzzing.md), with
// any value CDR can carry: any double bit pattern, any 32-bit integer, any bytes up to a NUL in
// a string, an optional present or absent. A boolean is 0 or 1 and the union's discriminator one
// of the two CouplingSource values: Cyclone's deserialiser drops a sample with anything else
// (docs/protocol.md, "Bad enum values"), and in C++ an enum holding another value is undefined
// behaviour that UBSan would report against the harness.
//
// Checks: from_wire throws only InvalidInput naming a field; the calculation returns a result
// without NaN (friction within [0, 1]) or throws an error reply_error_from classifies as a
// client's fault (never STATUS_INTERNAL_ERROR).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

#include "fuzz/fuzz_checks.h"
#include "fuzz/wire_bytes.h"
#include "protocol/calculation_traits.h"
#include "protocol/reply_status.h"
#include "protocol/samples.h"
#include "protocol/wire_requests.h"
#include "protocol/wire_results.h"
#include "service/compute.h"

namespace {

using gc::protocol::Calculation;

using namespace gc::fuzz;

// The members after the coupling, read whichever request this is, so a seed's layout does not
// depend on its calculation.
struct RequestTail {
  gearcoupling_OperatingPoint operating_point{};
  gearcoupling_ContactOptions options{};
  gearcoupling_FrictionMeasurement measurement{};
};

RequestTail read_tail(Bytes& in) {
  RequestTail tail;
  tail.operating_point = read_operating_point(in);
  tail.options = read_options(in);
  for (double* field : {&tail.measurement.torque_nm, &tail.measurement.misalignment_rad,
                        &tail.measurement.direction_rad, &tail.measurement.sensor_moment_y_nm,
                        &tail.measurement.sensor_moment_z_nm}) {
    *field = in.read<double>();
  }
  return tail;
}

template <typename WireRequest>
void assign_tail(const RequestTail& tail, WireRequest& request) {
  if constexpr (requires { request.operating_point; }) request.operating_point = tail.operating_point;
  if constexpr (requires { request.options; }) request.options = tail.options;
  if constexpr (requires { request.measurement; }) request.measurement = tail.measurement;
}

void check_result(const gc::ToothContact& r) { gc::fuzz::check(r, static_cast<int>(r.teeth.size())); }
void check_result(const gc::protocol::JamAngleResult& r) { gc::fuzz::check(r.jam); }
template <typename Result>
void check_result(const Result& r) { gc::fuzz::check(r); }

// What Service::answer does with a request that converted.
template <Calculation kCalculation>
void answer(const typename gc::protocol::CalculationTraits<kCalculation>::Request& request) {
  using T = gc::protocol::CalculationTraits<kCalculation>;
  try {
    std::optional<gc::CouplingGeometry> storage;
    const gc::CouplingGeometry& coupling = catalogue().resolve(request.coupling, storage);
    const typename T::Result result = gc::service::compute(coupling, request, {});
    check_result(result);
    gc::protocol::OwnedSample<typename T::WireReply> reply(T::reply_type());
    gc::protocol::to_wire(result, reply.get().result);
  } catch (...) {
    check_error(gc::protocol::reply_error_from(std::current_exception()));
  }
}

template <Calculation kCalculation>
void run(Bytes& in) {
  using T = gc::protocol::CalculationTraits<kCalculation>;
  typename T::WireRequest wire{};
  WireStorage storage;
  read_coupling(in, storage, wire.coupling);
  assign_tail(read_tail(in), wire);
  std::optional<typename T::Request> request;
  gc::fuzz::expect_result_or<gc::InvalidInput>([&] { request = gc::protocol::from_wire(wire); });
  if (request) answer<kCalculation>(*request);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  switch (in.read<std::uint8_t>() % 5) {
    case 0: run<Calculation::kToothContact>(in); break;
    case 1: run<Calculation::kJamAngle>(in); break;
    case 2: run<Calculation::kInducedMoments>(in); break;
    case 3: run<Calculation::kRestoringTorque>(in); break;
    case 4: run<Calculation::kFrictionEstimate>(in); break;
  }
  return 0;
}
