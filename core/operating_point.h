// The operating point every calculation takes: torque, misalignment and friction.
#pragma once

#include <string>
#include <string_view>

namespace gc {

class CouplingGeometry;

/// One load case. Validated against a coupling by validate_operating_point().
struct OperatingPoint {
  double torque_nm = 0.0;             ///< T, transmitted torque [N·m], in (0, 1e12]
  double misalignment_rad = 0.0;      ///< zeta, angular misalignment [rad], 0 <= zeta < jam angle
  double direction_rad = 0.0;         ///< beta, direction of the misalignment axis [rad]
  double friction_coefficient = 0.0;  ///< mu, tooth sliding friction [-], 0 <= mu <= 1
};

/// Throws InvalidInput naming the field ("operating_point.torque_nm", ...) unless `point` is a
/// load case the model covers for `coupling`: finite values, 0 < T <= 1e12 N·m, 0 <= zeta < jam angle,
/// 0 <= mu <= 1 and mu tan(zeta) < 1 (eq 37's denominator stays positive).
void validate_operating_point(const CouplingGeometry& coupling, const OperatingPoint& point);

/// Throws InvalidInput naming `field` unless 0 <= misalignment_rad < the coupling's jam angle:
/// beyond it the coupling jams, so no contact, moment or measurement of the model exists.
void require_below_jam_angle(const CouplingGeometry& coupling, std::string_view field,
                             double misalignment_rad);

}  // namespace gc
