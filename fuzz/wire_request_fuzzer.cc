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

#include "codec/coupling_catalog.h"
#include "fuzz/fuzz_checks.h"
#include "protocol/calculation_traits.h"
#include "protocol/reply_status.h"
#include "protocol/samples.h"
#include "protocol/wire_requests.h"
#include "protocol/wire_results.h"
#include "service/catalogue.h"
#include "service/compute.h"

namespace {

using gc::protocol::Calculation;

// Reads the input front to back; past its end every value is zero.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  template <typename T>
  T read() {
    T value{};
    const std::size_t n = std::min(sizeof(T), size_ - at_);
    std::memcpy(&value, data_ + at_, n);
    at_ += n;
    return value;
  }

  /// A u16 length, then that many bytes; the C string ends at the first NUL, as on the wire.
  std::string& read_string(std::string& storage) {
    const std::size_t length = std::min<std::size_t>(read<std::uint16_t>(), size_ - at_);
    storage.assign(reinterpret_cast<const char*>(data_ + at_), length);
    at_ += length;
    return storage;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

// The memory the C struct's pointers point into, alive while the request is converted.
struct WireStorage {
  std::string name;
  double crown_radius_m = 0.0;
  double sleeve_root_diameter_m = 0.0;
};

double* read_optional(Bytes& in, double& storage) {
  const bool present = in.read<std::uint8_t>() & 1;
  storage = in.read<double>();
  return present ? &storage : nullptr;
}

void read_definition(Bytes& in, WireStorage& storage, gearcoupling_CouplingDefinition& d) {
  d.name = in.read_string(storage.name).data();
  d.teeth = in.read<std::int32_t>();
  for (double* field : {&d.module_m, &d.pressure_angle_rad, &d.pitch_diameter_m,
                        &d.base_diameter_m, &d.outer_diameter_m, &d.root_diameter_m,
                        &d.center_distance_m, &d.backlash_m, &d.tooth_thickness_m,
                        &d.tool_tip_radius_m, &d.facewidth_m, &d.lead_modification_m,
                        &d.profile_tip_relief_m, &d.profile_relief_start_roll_rad}) {
    *field = in.read<double>();
  }
  d.crown_radius_m = read_optional(in, storage.crown_radius_m);
  for (double* field : {&d.form_factor_hub, &d.form_factor_sleeve, &d.youngs_modulus_pa,
                        &d.poisson_ratio, &d.design_misalignment_rad, &d.coupling_weight_n,
                        &d.shaft_weight_per_length_n_per_m, &d.shaft_length_m, &d.tilt_rad}) {
    *field = in.read<double>();
  }
  d.sleeve_root_diameter_m = read_optional(in, storage.sleeve_root_diameter_m);
  d.allowables.contact_stress_pa = in.read<double>();
  d.allowables.bending_stress_pa = in.read<double>();
}

void read_coupling(Bytes& in, WireStorage& storage, gearcoupling_CouplingRef& ref) {
  ref._d = static_cast<gearcoupling_CouplingSource>(in.read<std::uint8_t>() & 1);
  if (ref._d == gearcoupling_COUPLING_FROM_CATALOGUE) {
    ref._u.catalogue_name = in.read_string(storage.name).data();
  } else {
    read_definition(in, storage, ref._u.definition);
  }
}

// The members after the coupling, read whichever request this is, so a seed's layout does not
// depend on its calculation.
struct RequestTail {
  gearcoupling_OperatingPoint operating_point{};
  gearcoupling_ContactOptions options{};
  gearcoupling_FrictionMeasurement measurement{};
};

RequestTail read_tail(Bytes& in) {
  RequestTail tail;
  for (double* field : {&tail.operating_point.torque_nm, &tail.operating_point.misalignment_rad,
                        &tail.operating_point.direction_rad,
                        &tail.operating_point.friction_coefficient}) {
    *field = in.read<double>();
  }
  tail.options.load_sharing.tolerance = in.read<double>();
  tail.options.load_sharing.max_iterations = in.read<std::int32_t>();
  tail.options.slices = in.read<std::int32_t>();
  tail.options.spacing_error_m = in.read<double>();
  tail.options.min_load_fraction = in.read<double>();
  tail.options.continuous_quarter_sums = in.read<std::uint8_t>() & 1;
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

const gc::service::Catalogue& catalogue() {
  static const gc::service::Catalogue loaded(gc::codec::load_coupling_catalog(GC_FUZZ_CATALOG_DIR));
  return loaded;
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
    const gc::protocol::ReplyError error = gc::protocol::reply_error_from(std::current_exception());
    if (error.status == gearcoupling_STATUS_INTERNAL_ERROR) {
      gc::fuzz::fail("STATUS_INTERNAL_ERROR: " + error.message);
    }
    if (error.status == gearcoupling_STATUS_INVALID_INPUT && error.field.empty()) {
      gc::fuzz::fail("STATUS_INVALID_INPUT without a field: " + error.message);
    }
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
