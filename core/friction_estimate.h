// Friction coefficient from test-cell measurements (Section 3, eqs 1-4).
#pragma once

namespace gc {

class CouplingGeometry;

/// What the test cell records for one load case.
struct FrictionMeasurement {
  double torque_nm = 0.0;          ///< T [N·m], > 0
  double misalignment_rad = 0.0;   ///< zeta [rad], 0 <= zeta < pi/2
  double direction_rad = 0.0;      ///< beta [rad]
  double sensor_moment_y_nm = 0.0; ///< measured M_sy' [N·m]
  double sensor_moment_z_nm = 0.0; ///< measured M_sz' [N·m]
};

struct FrictionEstimate {
  double friction_coefficient = 0.0;  ///< mu, eq 4 [-] (may come out negative on bad data)
  double moment_z_dd_nm = 0.0;        ///< M_tz'' from the sensors, eq 3 [N·m]
};

/// Eq 3 rotates the sensor moments (self-weight added back, eq 48) into the double-prime frame;
/// eq 2 with eq 37's sign of mu, M_tz'' = T (sin zeta + mu cos zeta) / cos zeta, then gives
///   mu = M_tz'' / T - tan(zeta).                                            (eq 4 as read)
/// An approximation of eqs 42-47, not their inverse: docs/model.md states its accuracy.
FrictionEstimate estimate_friction(const CouplingGeometry& coupling,
                                   const FrictionMeasurement& measurement);

}  // namespace gc
