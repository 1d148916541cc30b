// The two NREL couplings of Table 1 as core value types, for tests that must not read files.
// tests/codec checks that data/couplings/*.textproto load to exactly these definitions.
#pragma once

#include <cmath>

#include "core/coupling_definition.h"
#include "core/coupling_geometry.h"

namespace gc::testing {

inline double deg(double degrees) { return degrees * M_PI / 180.0; }
inline double to_deg(double radians) { return radians * 180.0 / M_PI; }

inline CouplingDefinition nrel_upwind() {
  CouplingDefinition d;
  d.name = "nrel_upwind";
  d.teeth = 100;
  d.module_m = 0.01016;
  d.pressure_angle_rad = deg(20.0);
  d.pitch_diameter_m = 1.016;
  d.base_diameter_m = 0.95473;
  d.outer_diameter_m = 1.03632;
  d.root_diameter_m = 0.98877;
  d.center_distance_m = 0.0;
  d.backlash_m = 0.00064;
  d.tooth_thickness_m = 0.01555;
  d.tool_tip_radius_m = 0.00427;
  d.facewidth_m = 0.127;
  d.lead_modification_m = 0.00078;
  d.profile_tip_relief_m = 0.00046;
  d.profile_relief_start_roll_rad = deg(23.6);
  d.form_factor_hub = 0.45;
  d.form_factor_sleeve = 0.45;
  d.youngs_modulus_pa = 2.06e11;
  d.poisson_ratio = 0.3;
  d.design_misalignment_rad = 0.0;
  d.coupling_weight_n = 24000.0;
  d.shaft_weight_per_length_n_per_m = 21100.0;
  d.shaft_length_m = 2.8;
  d.tilt_rad = 0.0;
  d.allowables.contact_stress_pa = 1.1e9;
  d.allowables.bending_stress_pa = 3.1e8;
  return d;
}

inline CouplingDefinition nrel_downwind() {
  CouplingDefinition d = nrel_upwind();
  d.name = "nrel_downwind";
  d.root_diameter_m = 0.98795;
  d.backlash_m = 0.00197;
  d.tooth_thickness_m = 0.01603;
  d.tool_tip_radius_m = 0.00318;
  d.lead_modification_m = 0.0012;
  return d;
}

/// The upwind coupling's geometry, built once and shared (it is immutable).
inline const CouplingGeometry& upwind_geometry() {
  static const CouplingGeometry geometry(nrel_upwind());
  return geometry;
}

}  // namespace gc::testing
