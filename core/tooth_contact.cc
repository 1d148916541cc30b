#include "core/tooth_contact.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/coupling_geometry.h"
#include "core/model_error.h"

namespace gc {
namespace {

void validate_options(const ContactOptions& options) {
  if (options.slices < 2 || options.slices > 1000 || options.slices % 2 != 0) {
    throw InvalidInput("options.slices", options.slices, "an even number in [2, 1000]");
  }
  require_in_range("options.spacing_error_m", options.spacing_error_m, 0.0, 1e-3);
  require_in_range("options.min_load_fraction", options.min_load_fraction, 0.0, 1.0);
}

// Eq 11 with eq 12's R_c: maximum tooth separation, at a turning angle of 90 deg [m].
double max_separation_m(const CouplingGeometry& coupling, double misalignment_rad) {
  const double t = std::tan(misalignment_rad);
  return coupling.root_crown_radius_m() * t * t / (2.0 * std::tan(coupling.pressure_angle_rad()));
}

// Eq 13, with the residue of qN turned into an angle: a fraction of one tooth pitch 2 pi / N
// (as printed, a bare number of radians, it shifts the pattern by up to 14 deg and makes the
// moments jump; docs/model.md), plus the half tooth angle pi / N.
// The residue r = qN - int(qN) drops from 1 to 0 each time qN passes a whole number, so alpha
// steps back by a quarter pitch there. The continuous variant folds it, min(r, 1 - r): the
// paper's value for r <= 1/2, back to 0 at every whole qN without a step (docs/model.md).
double offset_alpha_rad(double q, int teeth, bool continuous) {
  const double q_n = q * teeth;
  const double residue = q_n - std::floor(q_n);
  const double used = continuous ? std::min(residue, 1.0 - residue) : residue;
  return used * (2.0 * M_PI / teeth) / 4.0 + M_PI / teeth;
}

// Eq 18: chord of the crown circle R_F cut at depth delta_d [m].
double contact_length_m(double crown_radius_m, double deformation_m) {
  if (deformation_m <= 0.0) return 0.0;
  const double depth = std::min(deformation_m, crown_radius_m);
  return 2.0 * std::sqrt(crown_radius_m * crown_radius_m -
                         (crown_radius_m - depth) * (crown_radius_m - depth));
}

// Eq 22 is a fitted curve; far below its range (z_e / z_o -> 0) eq 9 with that q no longer
// carries the transmitted load. Say so rather than return loads that do not add up to P_t.
void require_load_carried(const ToothContact& c, const OperatingPoint& point, double minimum) {
  const double carried = c.sum_tooth_loads_n / c.total_normal_load_n;
  if (carried >= minimum) return;
  std::ostringstream allowed;
  allowed.precision(3);
  allowed << "a torque at which eq 9's tooth loads carry at least " << 100 * minimum
          << " % of P_t at this misalignment; they carry " << 100 * carried
          << " % (z_e/z_o = " << c.load_sharing.ze_over_zo
          << ", light torque near the jam angle is outside eq 22's range)";
  throw InvalidInput("operating_point.torque_nm", point.torque_nm, allowed.str());
}

}  // namespace

ToothContact tooth_contact(const CouplingGeometry& coupling, const OperatingPoint& point,
                           const ContactOptions& options) {
  validate_operating_point(coupling, point);
  validate_options(options);
  const int n = coupling.teeth();
  const double stiffness = coupling.mesh_stiffness_n_per_m();
  const double crown = coupling.crown_radius_m();
  const double half_face = 0.5 * coupling.facewidth_m();

  ToothContact c;
  c.total_normal_load_n =
      point.torque_nm / (coupling.pitch_radius_m() * std::cos(coupling.pressure_angle_rad()));  // 7
  c.mean_tooth_load_n = c.total_normal_load_n / n;                                   // eq 20
  c.max_separation_m =
      max_separation_m(coupling, point.misalignment_rad) + options.spacing_error_m;  // eq 11
  c.load_sharing = solve_load_sharing(c.mean_tooth_load_n, stiffness, c.max_separation_m,
                                      options.load_sharing);                         // 20-22
  c.peak_tooth_load_n = c.mean_tooth_load_n / c.load_sharing.q;                      // eq 20
  c.elastic_deformation_m = c.peak_tooth_load_n / stiffness;                         // eq 10
  c.offset_alpha_rad =
      offset_alpha_rad(c.load_sharing.q, n, options.continuous_quarter_sums);          // eq 13
  c.max_contact_offset_m = crown * std::sin(point.misalignment_rad);                 // eq 15
  c.z_axis_angle_rad = coupling.pressure_angle_rad() + point.direction_rad;

  // Eq 9 as read: P_d = P_i [1 - (z_o / z_e) sin^2(theta_j)], clipped at zero.
  const double separation_ratio = c.max_separation_m / c.elastic_deformation_m;
  const double sin_alpha = std::sin(c.offset_alpha_rad);
  const double cos_alpha = std::cos(c.offset_alpha_rad);
  c.teeth.resize(n);
  for (int j = 0; j < n; ++j) {
    // theta_j = 2 pi j / N + alpha by the angle-sum rule on the coupling's tooth table.
    const double sin_theta = coupling.tooth_sin()[j] * cos_alpha + coupling.tooth_cos()[j] * sin_alpha;
    const double cos_theta = coupling.tooth_cos()[j] * cos_alpha - coupling.tooth_sin()[j] * sin_alpha;
    ToothLoad& tooth = c.teeth[j];
    tooth.angle_rad = 2.0 * M_PI * j / n + c.offset_alpha_rad;
    tooth.load_n =
        c.peak_tooth_load_n * std::max(0.0, 1.0 - separation_ratio * sin_theta * sin_theta);
    tooth.contact_offset_m = c.max_contact_offset_m * cos_theta;                     // eq 16
    tooth.deformation_m = tooth.load_n / stiffness;                                  // eq 17
    tooth.contact_length_m = contact_length_m(crown, tooth.deformation_m);           // eq 18
    const double begin = tooth.contact_offset_m - 0.5 * tooth.contact_length_m;    // eq 19
    const double end = tooth.contact_offset_m + 0.5 * tooth.contact_length_m;
    if (tooth.load_n > 0.0 && (begin < -half_face || end > half_face)) c.edge_loaded = true;
    tooth.zone_begin_m = std::clamp(begin, -half_face, half_face);
    tooth.zone_end_m = std::clamp(end, -half_face, half_face);
    if (tooth.load_n > 0.0) ++c.teeth_in_contact;
    if (tooth.load_n > c.max_tooth_load_n) {
      c.max_tooth_load_n = tooth.load_n;
      c.max_load_tooth = j;
    }
    c.sum_tooth_loads_n += tooth.load_n;
  }

  require_load_carried(c, point, options.min_load_fraction);
  c.slices = options.slices;
  c.continuous_quarter_sums = options.continuous_quarter_sums;
  const ToothLoad& governing = c.teeth[c.max_load_tooth];
  c.max_stress = tooth_stress(coupling, governing.load_n, governing.contact_length_m);
  return c;
}

Eigen::VectorXd ToothContact::slice_weights() const {
  Eigen::VectorXd weights(slices + 1);
  for (int l = -slices / 2; l <= slices / 2; ++l) {
    weights[l + slices / 2] = std::cos(M_PI * l / slices);  // eq 14
  }
  return weights;
}

Eigen::MatrixXd ToothContact::slice_loads() const {
  Eigen::VectorXd loads(static_cast<Eigen::Index>(teeth.size()));
  for (std::size_t j = 0; j < teeth.size(); ++j) loads[static_cast<Eigen::Index>(j)] = teeth[j].load_n;
  return loads * slice_weights().transpose();
}

double ToothContact::slice_position_m(int tooth, int slice) const {
  const ToothLoad& t = teeth.at(static_cast<std::size_t>(tooth));
  return t.contact_offset_m + static_cast<double>(slice) / slices * t.contact_length_m;
}

}  // namespace gc
