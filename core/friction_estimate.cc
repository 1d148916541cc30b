#include "core/friction_estimate.h"

#include <cmath>

#include "core/coupling_frame.h"
#include "core/coupling_geometry.h"
#include "core/induced_moments.h"
#include "core/model_error.h"

namespace gc {

FrictionEstimate estimate_friction(const CouplingGeometry& coupling,
                                   const FrictionMeasurement& measurement) {
  require_positive("measurement.torque_nm", measurement.torque_nm);
  require_in_range("measurement.misalignment_rad", measurement.misalignment_rad, 0.0, 1.5);
  require_finite("measurement.direction_rad", measurement.direction_rad);
  require_finite("measurement.sensor_moment_y_nm", measurement.sensor_moment_y_nm);
  require_finite("measurement.sensor_moment_z_nm", measurement.sensor_moment_z_nm);

  // Eq 48 undone: the coupling's own moment is the sensor moment plus the self-weight term.
  const Eigen::Vector2d coupling_moment(
      measurement.sensor_moment_y_nm + self_weight_moment_nm(coupling),
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
  return estimate;
}

}  // namespace gc
