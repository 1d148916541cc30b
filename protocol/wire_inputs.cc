#include "protocol/wire_inputs.h"

#include "protocol/field_copy.h"

#include <cstring>
#include <optional>
#include <string_view>

#include "core/model_error.h"
#include "protocol/reply_status.h"

namespace gc::protocol {
namespace {

double* wire_optional(const std::optional<double>& value) {
  if (!value) return nullptr;
  auto* out = static_cast<double*>(dds_alloc(sizeof(double)));
  *out = *value;
  return out;
}

std::optional<double> from_wire_optional(const double* value) {
  if (value == nullptr) return std::nullopt;
  return *value;
}

// The message shows the length and the first bytes only: the name may be megabytes long.
std::string bounded_name(const std::string& field, const char* text) {
  if (text == nullptr) return "";
  const std::size_t bytes = std::strlen(text);
  if (bytes <= kMaxNameBytes) return std::string(text, bytes);
  throw InvalidInput(field, "\"" + echo_text(std::string_view(text, bytes), 64) +
                                "\" is too long: allowed at most " +
                                std::to_string(kMaxNameBytes) + " bytes");
}

}  // namespace

char* wire_string(const std::string& text) { return dds_string_dup(text.c_str()); }

// The numeric fields of a coupling definition, one list for both directions: `copy(core_field,
// wire_field)` is called for each; the name and the optional fields are handled by the callers.
template <typename Core, typename Wire, typename Copy>
void coupling_numeric_fields(Core& core, Wire& wire, Copy copy) {
  copy(core.teeth, wire.teeth);
  copy(core.module_m, wire.module_m);
  copy(core.pressure_angle_rad, wire.pressure_angle_rad);
  copy(core.pitch_diameter_m, wire.pitch_diameter_m);
  copy(core.base_diameter_m, wire.base_diameter_m);
  copy(core.outer_diameter_m, wire.outer_diameter_m);
  copy(core.root_diameter_m, wire.root_diameter_m);
  copy(core.center_distance_m, wire.center_distance_m);
  copy(core.backlash_m, wire.backlash_m);
  copy(core.tooth_thickness_m, wire.tooth_thickness_m);
  copy(core.tool_tip_radius_m, wire.tool_tip_radius_m);
  copy(core.facewidth_m, wire.facewidth_m);
  copy(core.lead_modification_m, wire.lead_modification_m);
  copy(core.profile_tip_relief_m, wire.profile_tip_relief_m);
  copy(core.profile_relief_start_roll_rad, wire.profile_relief_start_roll_rad);
  copy(core.form_factor_hub, wire.form_factor_hub);
  copy(core.form_factor_sleeve, wire.form_factor_sleeve);
  copy(core.youngs_modulus_pa, wire.youngs_modulus_pa);
  copy(core.poisson_ratio, wire.poisson_ratio);
  copy(core.design_misalignment_rad, wire.design_misalignment_rad);
  copy(core.coupling_weight_n, wire.coupling_weight_n);
  copy(core.shaft_weight_per_length_n_per_m, wire.shaft_weight_per_length_n_per_m);
  copy(core.shaft_length_m, wire.shaft_length_m);
  copy(core.tilt_rad, wire.tilt_rad);
  copy(core.allowables.contact_stress_pa, wire.allowables.contact_stress_pa);
  copy(core.allowables.bending_stress_pa, wire.allowables.bending_stress_pa);
}

void to_wire(const CouplingDefinition& in, gearcoupling_CouplingDefinition& out) {
  out.name = wire_string(in.name);
  coupling_numeric_fields(in, out, kToWire);
  out.crown_radius_m = wire_optional(in.crown_radius_m);
  out.sleeve_root_diameter_m = wire_optional(in.sleeve_root_diameter_m);
}

CouplingDefinition from_wire(const gearcoupling_CouplingDefinition& in) {
  CouplingDefinition out;
  out.name = bounded_name("coupling.name", in.name);
  coupling_numeric_fields(out, in, kFromWire);
  out.crown_radius_m = from_wire_optional(in.crown_radius_m);
  out.sleeve_root_diameter_m = from_wire_optional(in.sleeve_root_diameter_m);
  return out;
}

void to_wire(const CouplingRef& in, gearcoupling_CouplingRef& out) {
  if (const auto* name = std::get_if<CatalogueName>(&in)) {
    out._d = gearcoupling_COUPLING_FROM_CATALOGUE;
    out._u.catalogue_name = wire_string(name->name);
  } else {
    out._d = gearcoupling_COUPLING_INLINE;
    to_wire(std::get<CouplingDefinition>(in), out._u.definition);
  }
}

CouplingRef from_wire(const gearcoupling_CouplingRef& in) {
  switch (in._d) {
    case gearcoupling_COUPLING_FROM_CATALOGUE:
      return CatalogueName{bounded_name("coupling.catalogue_name", in._u.catalogue_name)};
    case gearcoupling_COUPLING_INLINE:
      return from_wire(in._u.definition);
  }
  throw InvalidInput("coupling", static_cast<double>(in._d),
                     "COUPLING_FROM_CATALOGUE (0) or COUPLING_INLINE (1)");
}

void to_wire(const OperatingPoint& in, gearcoupling_OperatingPoint& out) {
  out.torque_nm = in.torque_nm;
  out.misalignment_rad = in.misalignment_rad;
  out.direction_rad = in.direction_rad;
  out.friction_coefficient = in.friction_coefficient;
}

OperatingPoint from_wire(const gearcoupling_OperatingPoint& in) {
  return OperatingPoint{in.torque_nm, in.misalignment_rad, in.direction_rad,
                        in.friction_coefficient};
}

void to_wire(const ContactOptions& in, gearcoupling_ContactOptions& out) {
  out.load_sharing.tolerance = in.load_sharing.tolerance;
  out.load_sharing.max_iterations = in.load_sharing.max_iterations;
  out.slices = in.slices;
  out.spacing_error_m = in.spacing_error_m;
  out.min_load_fraction = in.min_load_fraction;
  out.continuous_quarter_sums = in.continuous_quarter_sums;
}

ContactOptions from_wire(const gearcoupling_ContactOptions& in) {
  ContactOptions out;
  out.load_sharing.tolerance = in.load_sharing.tolerance;
  out.load_sharing.max_iterations = in.load_sharing.max_iterations;
  out.slices = in.slices;
  out.spacing_error_m = in.spacing_error_m;
  out.min_load_fraction = in.min_load_fraction;
  out.continuous_quarter_sums = in.continuous_quarter_sums;
  return out;
}

void to_wire(const FrictionMeasurement& in, gearcoupling_FrictionMeasurement& out) {
  out.torque_nm = in.torque_nm;
  out.misalignment_rad = in.misalignment_rad;
  out.direction_rad = in.direction_rad;
  out.sensor_moment_y_nm = in.sensor_moment_y_nm;
  out.sensor_moment_z_nm = in.sensor_moment_z_nm;
}

FrictionMeasurement from_wire(const gearcoupling_FrictionMeasurement& in) {
  return FrictionMeasurement{in.torque_nm, in.misalignment_rad, in.direction_rad,
                             in.sensor_moment_y_nm, in.sensor_moment_z_nm};
}

}  // namespace gc::protocol
