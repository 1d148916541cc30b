// The input layout the wire fuzzers share (docs/fuzzing.md, "wire_request_fuzzer's input"):
// values read front to back into the IDL's C types, any double bit pattern, any 32-bit integer,
// any bytes up to a NUL in a string; and the service's catalogue and error classification.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "codec/coupling_catalog.h"
#include "fuzz/fuzz_checks.h"
#include "protocol/reply_status.h"
#include "service/catalogue.h"

namespace gc::fuzz {

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

inline double* read_optional(Bytes& in, double& storage) {
  const bool present = in.read<std::uint8_t>() & 1;
  storage = in.read<double>();
  return present ? &storage : nullptr;
}

inline void read_definition(Bytes& in, WireStorage& storage, gearcoupling_CouplingDefinition& d) {
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

inline void read_coupling(Bytes& in, WireStorage& storage, gearcoupling_CouplingRef& ref) {
  ref._d = static_cast<gearcoupling_CouplingSource>(in.read<std::uint8_t>() & 1);
  if (ref._d == gearcoupling_COUPLING_FROM_CATALOGUE) {
    ref._u.catalogue_name = in.read_string(storage.name).data();
  } else {
    read_definition(in, storage, ref._u.definition);
  }
}

inline gearcoupling_OperatingPoint read_operating_point(Bytes& in) {
  gearcoupling_OperatingPoint point{};
  for (double* field : {&point.torque_nm, &point.misalignment_rad, &point.direction_rad,
                        &point.friction_coefficient}) {
    *field = in.read<double>();
  }
  return point;
}

inline gearcoupling_ContactOptions read_options(Bytes& in) {
  gearcoupling_ContactOptions options{};
  options.load_sharing.tolerance = in.read<double>();
  options.load_sharing.max_iterations = in.read<std::int32_t>();
  options.slices = in.read<std::int32_t>();
  options.spacing_error_m = in.read<double>();
  options.min_load_fraction = in.read<double>();
  options.continuous_quarter_sums = in.read<std::uint8_t>() & 1;
  return options;
}

inline const gc::service::Catalogue& catalogue() {
  static const gc::service::Catalogue loaded(gc::codec::load_coupling_catalog(GC_FUZZ_CATALOG_DIR));
  return loaded;
}

// What the service may send back: an error reply_error_from classifies as a client's fault,
// never STATUS_INTERNAL_ERROR, and an invalid input always names its field.
inline void check_error(const gc::protocol::ReplyError& error) {
  if (error.status == gearcoupling_STATUS_INTERNAL_ERROR) {
    gc::fuzz::fail("STATUS_INTERNAL_ERROR: " + error.message);
  }
  if (error.status == gearcoupling_STATUS_INVALID_INPUT && error.field.empty()) {
    gc::fuzz::fail("STATUS_INVALID_INPUT without a field: " + error.message);
  }
}

}  // namespace gc::fuzz
