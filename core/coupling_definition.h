// What a user states about a crowned-tooth gear coupling: Table 1 of the paper plus the inputs
// the model needs and the paper omits. SI units throughout; angles in radians.
#pragma once

#include <optional>
#include <string>

namespace gc {

/// Material allowables for the safety factors (stress.h). Not in the paper (it defers to its
/// reference [18]); the bundled couplings state theirs in data/couplings/.
struct MaterialAllowables {
  double contact_stress_pa = 0.0;  ///< allowable Hertzian contact stress [Pa]
  double bending_stress_pa = 0.0;  ///< allowable tooth-root bending stress [Pa]
};

/// Everything the model reads about one coupling. Validated and completed by CouplingGeometry.
struct CouplingDefinition {
  std::string name;

  // --- Table 1 ---------------------------------------------------------------------------
  int teeth = 0;                         ///< N [-]
  double module_m = 0.0;                 ///< m = D / N [m] (Table 1's "Module (1/mm)" is mm)
  double pressure_angle_rad = 0.0;       ///< phi, normal pressure angle [rad]
  double pitch_diameter_m = 0.0;         ///< D = 2R [m]
  double base_diameter_m = 0.0;          ///< D cos(phi) [m]
  double outer_diameter_m = 0.0;         ///< hub tip diameter [m]
  double root_diameter_m = 0.0;          ///< hub root diameter [m]
  double center_distance_m = 0.0;       ///< 0 for a coupling [m]
  double backlash_m = 0.0;               ///< b = delta_b, circular backlash [m]
  double tooth_thickness_m = 0.0;        ///< t_c1, hub circular tooth thickness [m]
  double tool_tip_radius_m = 0.0;        ///< [m], informational
  double facewidth_m = 0.0;              ///< F [m]
  double lead_modification_m = 0.0;      ///< d, crown drop per flank at the tooth edges [m]
  double profile_tip_relief_m = 0.0;     ///< [m], informational
  double profile_relief_start_roll_rad = 0.0;  ///< [rad], informational

  // --- What the model needs and the paper does not give -----------------------------------
  /// R_F, hub face crown radius [m]. When absent it is derived from the lead modification:
  /// R_F = ((F/2)^2 + d^2) / (2 d) (crown_radius.h).
  std::optional<double> crown_radius_m;
  double form_factor_hub = 0.0;          ///< Y1, AGMA form factor of the hub tooth [-]
  double form_factor_sleeve = 0.0;       ///< Y2, AGMA form factor of the sleeve tooth [-]
  double youngs_modulus_pa = 0.0;        ///< E [Pa]
  double poisson_ratio = 0.0;            ///< nu [-], for the Hertzian stress only
  double design_misalignment_rad = 0.0;  ///< i_d, eq 12 [rad]
  double coupling_weight_n = 0.0;        ///< W_c, hub weight carried by the sleeve [N]
  double shaft_weight_per_length_n_per_m = 0.0;  ///< w_sh [N/m]
  double shaft_length_m = 0.0;           ///< L_s [m]
  double tilt_rad = 0.0;                 ///< gamma, shaft tilt from horizontal [rad]
  /// Sleeve root (major) diameter [m], for the design root clearance Delta_r of Section 4.4.
  /// When absent the sleeve is taken to mirror the hub's dedendum: D + (D - root diameter).
  std::optional<double> sleeve_root_diameter_m;
  MaterialAllowables allowables;
};

}  // namespace gc
