#include "core/friction_estimate.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/coupling_frame.h"
#include "core/coupling_geometry.h"
#include "core/induced_moments.h"
#include "core/model_error.h"
#include "core/operating_point.h"

namespace gc {
namespace {

void validate(const CouplingGeometry& coupling, const FrictionMeasurement& measurement) {
  require_positive("measurement.torque_nm", measurement.torque_nm);
  // Beyond the jam angle the coupling jams: no measurement there is one the model describes.
  require_below_jam_angle(coupling, "measurement.misalignment_rad", measurement.misalignment_rad);
  require_finite("measurement.direction_rad", measurement.direction_rad);
  require_finite("measurement.sensor_moment_y_nm", measurement.sensor_moment_y_nm);
  require_finite("measurement.sensor_moment_z_nm", measurement.sensor_moment_z_nm);
}

// M_tz'' = sin(psi) (M_sy' + W term) + cos(psi) M_sz' (eq 3, the second row of R(psi)^T).
// mu lies in [0, 1] exactly when M_tz'' lies in [T tan(zeta), T (tan(zeta) + 1)]. An estimate
// outside is no friction coefficient (issue 9: -1.51 and 2.28e301 were returned as results), so
// the sensor moment that dominates M_tz'' is named with the range that, the other inputs as
// given, would bring mu into [0, 1].
[[noreturn]] void reject_estimate(const FrictionMeasurement& m, double psi, double self_weight_nm,
                                  double mu) {
  const double s = std::sin(psi);
  const double c = std::cos(psi);
  const double from_y = s * (m.sensor_moment_y_nm + self_weight_nm);
  const double from_z = c * m.sensor_moment_z_nm;
  const bool blame_z = std::abs(from_z) != std::abs(from_y) ? std::abs(from_z) > std::abs(from_y)
                                                             : std::abs(c) >= std::abs(s);
  const double lo = m.torque_nm * std::tan(m.misalignment_rad);
  const double hi = lo + m.torque_nm;
  const double rest = blame_z ? from_y : from_z;
  const double coefficient = blame_z ? c : s;
  const double offset = blame_z ? 0.0 : self_weight_nm;
  const double a = (lo - rest) / coefficient - offset;
  const double b = (hi - rest) / coefficient - offset;
  std::string allowed = "[";  // appended, not "[" + ...: GCC 12's -Wrestrict misfires on that (PR 105651)
  allowed += format_precise(std::min(a, b)) + ", " + format_precise(std::max(a, b)) +
      "] N·m, the range that makes eq 4's mu = M_tz''/T - tan(zeta) a friction coefficient in "
      "[0, 1] with the other inputs as given; these give mu = " + format_number(mu);
  throw InvalidInput(blame_z ? "measurement.sensor_moment_z_nm" : "measurement.sensor_moment_y_nm",
                     blame_z ? m.sensor_moment_z_nm : m.sensor_moment_y_nm, allowed);
}

}  // namespace

FrictionEstimate estimate_friction(const CouplingGeometry& coupling,
                                   const FrictionMeasurement& measurement) {
  validate(coupling, measurement);
  // Eq 48 undone: the coupling's own moment is the sensor moment plus the self-weight term.
  const double self_weight_nm = self_weight_moment_nm(coupling);
  const Eigen::Vector2d coupling_moment(measurement.sensor_moment_y_nm + self_weight_nm,
                                        measurement.sensor_moment_z_nm);
  // Eq 3: into the double-prime frame with the inverse (transpose) of eqs 44-45.
  const Eigen::Vector2d double_prime =
      double_prime_to_coupling(coupling.pressure_angle_rad(), measurement.direction_rad)
          .transpose() *
      coupling_moment;
  FrictionEstimate estimate;
  estimate.moment_z_dd_nm = double_prime.y();
  // Eq 4 as read (eq 2 with eq 37's sign of mu).
  estimate.friction_coefficient =
      estimate.moment_z_dd_nm / measurement.torque_nm - std::tan(measurement.misalignment_rad);
  if (!std::isfinite(estimate.friction_coefficient)) {
    throw InvalidInput("measurement.torque_nm", measurement.torque_nm,
                       "a torque for which M_tz'' / T (eq 4) is finite");
  }
  if (estimate.friction_coefficient < 0.0 || estimate.friction_coefficient > 1.0) {
    reject_estimate(measurement, coupling.pressure_angle_rad() + measurement.direction_rad,
                    self_weight_nm, estimate.friction_coefficient);
  }
  return estimate;
}

}  // namespace gc
