// Friction coefficient from test-cell measurements (Section 3, eqs 1-4).
#pragma once

namespace gc {

class CouplingGeometry;

/// What the test cell records for one load case.
struct FrictionMeasurement {
  double torque_nm = 0.0;          ///< T [N·m], > 0
  double misalignment_rad = 0.0;   ///< zeta [rad], 0 <= zeta < the coupling's jam angle
  double direction_rad = 0.0;      ///< beta [rad]
  double sensor_moment_y_nm = 0.0; ///< measured M_sy' [N·m]
  double sensor_moment_z_nm = 0.0; ///< measured M_sz' [N·m]
};

struct FrictionEstimate {
  double friction_coefficient = 0.0;  ///< mu, eq 4 [-], in [0, 1]
  double moment_z_dd_nm = 0.0;        ///< M_tz'' from the sensors, eq 3 [N·m]
};

/// Eq 3 rotates the sensor moments (self-weight added back, eq 48) into the double-prime frame;
/// eq 2 with eq 37's sign of mu, M_tz'' = T (sin zeta + mu cos zeta) / cos zeta, then gives
///   mu = M_tz'' / T - tan(zeta).                                            (eq 4 as read)
/// An approximation of eqs 42-47, not their inverse: docs/model.md states its accuracy.
/// Throws InvalidInput naming the measurement field: torque <= 0, misalignment outside
/// [0, jam angle), non-finite values, or moments for which mu is not finite or lies outside
/// [0, 1] (then the sensor moment that dominates M_tz'' is named, with the range that would
/// give a mu in [0, 1] with the other inputs as given): such an estimate is not a result.
FrictionEstimate estimate_friction(const CouplingGeometry& coupling,
                                   const FrictionMeasurement& measurement);

}  // namespace gc
