#include "tests/diagnosis/independent/truth_physics.h"

#include <cmath>

#include "core/coupling_frame.h"
#include "core/induced_moments.h"

namespace gc::independent {

Eigen::Vector2d contact_moments(const CouplingGeometry& geometry, const OperatingPoint& point,
                                const ContactOptions& options, double frame_shift_rad) {
  const InducedMoments m = induced_moments(geometry, point, options);
  return double_prime_to_coupling(frame_shift_rad, point.direction_rad) *
         Eigen::Vector2d(m.moment_y_dd_nm, m.moment_z_dd_nm);
}

SensorMoments with_contact_change(const CouplingModel& base, const MeasurementSample& sample,
                                  const ContactChange& change) {
  const ModelPrediction p = base.predict(sample);
  OperatingPoint point = p.state.point;
  double shift_rad = p.state.frame_shift_rad;
  const Eigen::Vector2d before = contact_moments(base.geometry(), point, p.state.contact, shift_rad);
  change(point, shift_rad);
  const Eigen::Vector2d after = contact_moments(base.geometry(), point, p.state.contact, shift_rad);
  return {p.moments.y_nm + after.x() - before.x(), p.moments.z_nm + after.y() - before.y()};
}

Eigen::Vector2d contact_moment_direction(const CouplingModel& base, const MeasurementSample& sample) {
  const ModelPrediction p = base.predict(sample);
  const Eigen::Vector2d m =
      contact_moments(base.geometry(), p.state.point, p.state.contact, p.state.frame_shift_rad);
  const double norm = m.norm();
  return norm > 0.0 ? Eigen::Vector2d(m / norm) : Eigen::Vector2d::Zero();
}

MeasurementSample with_added_misalignment(MeasurementSample sample, double zeta0_rad, double beta0_rad) {
  const double a = sample.misalignment_rad * std::cos(sample.direction_rad) + zeta0_rad * std::cos(beta0_rad);
  const double b = sample.misalignment_rad * std::sin(sample.direction_rad) + zeta0_rad * std::sin(beta0_rad);
  sample.misalignment_rad = std::hypot(a, b);
  sample.direction_rad = std::atan2(b, a);
  return sample;
}

double weight_moment_nm(const CouplingDefinition& c) {
  return (c.coupling_weight_n + 0.5 * c.shaft_weight_per_length_n_per_m * c.shaft_length_m) *
         c.shaft_length_m * std::cos(c.tilt_rad);
}

}  // namespace gc::independent
