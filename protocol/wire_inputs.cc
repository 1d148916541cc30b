#include "protocol/wire_inputs.h"

#include <optional>

#include "core/model_error.h"

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

}  // namespace

char* wire_string(const std::string& text) { return dds_string_dup(text.c_str()); }

void to_wire(const CouplingDefinition& in, gearcoupling_CouplingDefinition& out) {
  out.name = wire_string(in.name);
  out.teeth = in.teeth;
  out.module_m = in.module_m;
  out.pressure_angle_rad = in.pressure_angle_rad;
  out.pitch_diameter_m = in.pitch_diameter_m;
  out.base_diameter_m = in.base_diameter_m;
  out.outer_diameter_m = in.outer_diameter_m;
  out.root_diameter_m = in.root_diameter_m;
  out.center_distance_m = in.center_distance_m;
  out.backlash_m = in.backlash_m;
  out.tooth_thickness_m = in.tooth_thickness_m;
  out.tool_tip_radius_m = in.tool_tip_radius_m;
  out.facewidth_m = in.facewidth_m;
  out.lead_modification_m = in.lead_modification_m;
  out.profile_tip_relief_m = in.profile_tip_relief_m;
  out.profile_relief_start_roll_rad = in.profile_relief_start_roll_rad;
  out.crown_radius_m = wire_optional(in.crown_radius_m);
  out.form_factor_hub = in.form_factor_hub;
  out.form_factor_sleeve = in.form_factor_sleeve;
  out.youngs_modulus_pa = in.youngs_modulus_pa;
  out.poisson_ratio = in.poisson_ratio;
  out.design_misalignment_rad = in.design_misalignment_rad;
  out.coupling_weight_n = in.coupling_weight_n;
  out.shaft_weight_per_length_n_per_m = in.shaft_weight_per_length_n_per_m;
  out.shaft_length_m = in.shaft_length_m;
  out.tilt_rad = in.tilt_rad;
  out.sleeve_root_diameter_m = wire_optional(in.sleeve_root_diameter_m);
  out.allowables.contact_stress_pa = in.allowables.contact_stress_pa;
  out.allowables.bending_stress_pa = in.allowables.bending_stress_pa;
}

CouplingDefinition from_wire(const gearcoupling_CouplingDefinition& in) {
  CouplingDefinition out;
  out.name = in.name != nullptr ? in.name : "";
  out.teeth = in.teeth;
  out.module_m = in.module_m;
  out.pressure_angle_rad = in.pressure_angle_rad;
  out.pitch_diameter_m = in.pitch_diameter_m;
  out.base_diameter_m = in.base_diameter_m;
  out.outer_diameter_m = in.outer_diameter_m;
  out.root_diameter_m = in.root_diameter_m;
  out.center_distance_m = in.center_distance_m;
  out.backlash_m = in.backlash_m;
  out.tooth_thickness_m = in.tooth_thickness_m;
  out.tool_tip_radius_m = in.tool_tip_radius_m;
  out.facewidth_m = in.facewidth_m;
  out.lead_modification_m = in.lead_modification_m;
  out.profile_tip_relief_m = in.profile_tip_relief_m;
  out.profile_relief_start_roll_rad = in.profile_relief_start_roll_rad;
  out.crown_radius_m = from_wire_optional(in.crown_radius_m);
  out.form_factor_hub = in.form_factor_hub;
  out.form_factor_sleeve = in.form_factor_sleeve;
  out.youngs_modulus_pa = in.youngs_modulus_pa;
  out.poisson_ratio = in.poisson_ratio;
  out.design_misalignment_rad = in.design_misalignment_rad;
  out.coupling_weight_n = in.coupling_weight_n;
  out.shaft_weight_per_length_n_per_m = in.shaft_weight_per_length_n_per_m;
  out.shaft_length_m = in.shaft_length_m;
  out.tilt_rad = in.tilt_rad;
  out.sleeve_root_diameter_m = from_wire_optional(in.sleeve_root_diameter_m);
  out.allowables.contact_stress_pa = in.allowables.contact_stress_pa;
  out.allowables.bending_stress_pa = in.allowables.bending_stress_pa;
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
      return CatalogueName{in._u.catalogue_name != nullptr ? in._u.catalogue_name : ""};
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
}

ContactOptions from_wire(const gearcoupling_ContactOptions& in) {
  ContactOptions out;
  out.load_sharing.tolerance = in.load_sharing.tolerance;
  out.load_sharing.max_iterations = in.load_sharing.max_iterations;
  out.slices = in.slices;
  out.spacing_error_m = in.spacing_error_m;
  out.min_load_fraction = in.min_load_fraction;
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
