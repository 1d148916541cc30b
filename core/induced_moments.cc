#include "core/induced_moments.h"

#include <algorithm>
#include <cmath>

#include "core/coupling_frame.h"
#include "core/coupling_geometry.h"
#include "core/tooth_load_pattern.h"

namespace gc {

namespace {

// Eq 37's W_d / P_d from cos and sin of zeta.
double axial_load_factor(double cos_misalignment, double sin_misalignment, double friction) {
  return (friction * cos_misalignment + sin_misalignment) /
         (cos_misalignment - friction * sin_misalignment);  // eq 37
}

}  // namespace

double axial_load_factor(double misalignment_rad, double friction) {
  return axial_load_factor(std::cos(misalignment_rad), std::sin(misalignment_rad), friction);
}

double axial_tooth_load_n(double tooth_load_n, double misalignment_rad, double friction) {
  return tooth_load_n * axial_load_factor(misalignment_rad, friction);
}

double self_weight_moment_nm(const CouplingGeometry& coupling) {
  const CouplingDefinition& d = coupling.definition();
  const double cos_tilt = std::cos(d.tilt_rad);
  return d.coupling_weight_n * cos_tilt * d.shaft_length_m +
         d.shaft_weight_per_length_n_per_m * cos_tilt * d.shaft_length_m * d.shaft_length_m / 2.0;
}

namespace {

// Eqs 37-43 for a tooth load pattern (eq 13's alpha, eq 15's F_i, the load-sharing ratio q,
// zeta's sine and cosine);
// `load_of(j)` is P_d of tooth j (eq 9). `continuous`: ContactOptions'. A template, not a
// std::function: it runs for every tooth summed of every evaluation.
template <typename LoadOf>
QuarterSums quarter_sums(const CouplingGeometry& coupling, const OperatingPoint& point,
                         const ToothLoadPattern& pattern, bool continuous, const LoadOf& load_of) {
  const double q_n = pattern.load_sharing.q * coupling.teeth();
  const double radius = coupling.pitch_radius_m();
  const double axial_factor = axial_load_factor(pattern.cos_misalignment, pattern.sin_misalignment,
                                                point.friction_coefficient);
  const double max_offset = pattern.max_contact_offset_m;  // R_F sin(zeta), eq 15

  // Eqs 42-43: the symmetric quarter j = 0 .. int(qN/4), four times.
  const double quarter = q_n / 4.0;
  const int last = static_cast<int>(quarter);
  double sum_y = 0.0;
  double sum_z = 0.0;
  // cos(2 pi j / (qN) + alpha) of eq 40 by turning (cos, sin) a step of 2 pi / (qN) per tooth: a
  // cosine per tooth was a third of a diagnosis' time, and the turns drift by a few ulp.
  const double step = 2.0 * M_PI / q_n;
  const double cos_step = std::cos(step), sin_step = std::sin(step);
  double cos_offset = pattern.cos_alpha, sin_offset = pattern.sin_alpha;
  const auto add_tooth = [&](int j, double weight) {
    const double load = load_of(j);
    const double projection = pattern.cos_theta(coupling, j);  // cos(2 pi j/N + alpha)
    const double offset = max_offset * cos_offset;             // f_d, eq 40
    const double arm = std::sqrt(radius * radius - offset * offset);  // R_d, eq 39
    const double axial = load * axial_factor;                         // W_d, eq 37
    sum_z += weight * projection * axial * arm;     // M_dz'' = W_d R_d, eq 38
    sum_y += weight * projection * load * offset;   // M_dy'' = P_d f_d, eq 41
    const double turned = cos_offset * cos_step - sin_offset * sin_step;
    sin_offset = sin_offset * cos_step + cos_offset * sin_step;
    cos_offset = turned;
  };
  for (int j = 0; j <= last; ++j) add_tooth(j, 1.0);
  // The continuous variant (docs/model.md): as qN/4 grows from one whole number to the next,
  // the next tooth enters the quarter in proportion instead of all at once, so the sums run
  // from the paper's value at int(qN/4) to its value at int(qN/4) + 1 without a step.
  const double entering = quarter - last;
  const bool fractional_tooth = continuous && entering > 0.0;
  if (fractional_tooth) add_tooth(last + 1, entering);
  return {4.0 * sum_y, 4.0 * sum_z, 4 * (last + 1 + (fractional_tooth ? 1 : 0))};  // eqs 43, 42
}

}  // namespace

namespace {

// Eqs 36-48 from the pattern of a solved contact.
InducedMoments moments_of(const CouplingGeometry& coupling, const OperatingPoint& point,
                          const ToothLoadPattern& pattern, bool continuous) {
  const QuarterSums sums = quarter_sums(coupling, point, pattern, continuous,
                                        [&](int j) { return pattern.load_n(coupling, j); });
  InducedMoments m;
  m.teeth_summed = sums.teeth_summed;
  m.moment_y_dd_nm = sums.moment_y_dd_nm;  // eq 43
  m.moment_z_dd_nm = sums.moment_z_dd_nm;  // eq 42
  const Eigen::Vector2d global =
      double_prime_to_coupling(coupling.pressure_angle_rad(), point.direction_rad) *
      Eigen::Vector2d(m.moment_y_dd_nm, m.moment_z_dd_nm);  // eqs 44-47
  m.moment_y_nm = global.x();
  m.moment_z_nm = global.y();
  m.self_weight_moment_nm = self_weight_moment_nm(coupling);
  m.sensor_moment_y_nm = m.moment_y_nm - m.self_weight_moment_nm;  // eq 48
  m.sensor_moment_z_nm = m.moment_z_nm;
  m.magnitude_nm = global.norm();
  m.direction_rad = std::atan2(global.y(), global.x());
  return m;
}

}  // namespace

InducedMoments induced_moments(const CouplingGeometry& coupling, const OperatingPoint& point,
                               const ToothContact& contact) {
  // P_d of eq 9 from the contact's members, as its table holds them: a contact solved without
  // listing its teeth (tooth_contact_without_teeth) gives the same moments.
  ToothLoadPattern pattern = tooth_load_pattern(contact);
  pattern.sin_misalignment = std::sin(point.misalignment_rad);
  pattern.cos_misalignment = std::cos(point.misalignment_rad);
  return moments_of(coupling, point, pattern, contact.continuous_quarter_sums);
}

InducedMoments induced_moments(const CouplingGeometry& coupling, const OperatingPoint& point,
                               const ContactOptions& options, ToothContact& contact) {
  const ToothLoadPattern pattern = tooth_contact_without_teeth(coupling, point, options, contact);
  return moments_of(coupling, point, pattern, contact.continuous_quarter_sums);
}

InducedMoments induced_moments(const CouplingGeometry& coupling, const OperatingPoint& point,
                               const ContactOptions& options) {
  ToothContact contact;
  return induced_moments(coupling, point, options, contact);
}

QuarterSums double_prime_moments(const CouplingGeometry& coupling, const OperatingPoint& point,
                                 const ContactOptions& options) {
  const ToothLoadPattern pattern = tooth_load_pattern(coupling, point, options);
  // The sum tooth_contact() reports: the same refusals.
  require_load_carried(pattern, sum_of_tooth_loads_n(coupling, pattern), point, options.min_load_fraction);
  return quarter_sums(coupling, point, pattern, options.continuous_quarter_sums,
                      [&](int j) { return pattern.load_n(coupling, j); });
}

}  // namespace gc
