#include "core/tooth_contact.h"

#include <algorithm>
#include <cmath>

#include "core/coupling_geometry.h"
#include "core/tooth_load_pattern.h"

namespace gc {
namespace {

// Eq 18: chord of the crown circle R_F cut at depth delta_d [m].
double contact_length_m(double crown_radius_m, double deformation_m) {
  if (deformation_m <= 0.0) return 0.0;
  const double depth = std::min(deformation_m, crown_radius_m);
  return 2.0 * std::sqrt(crown_radius_m * crown_radius_m -
                         (crown_radius_m - depth) * (crown_radius_m - depth));
}

}  // namespace

ToothContact tooth_contact(const CouplingGeometry& coupling, const OperatingPoint& point,
                           const ContactOptions& options) {
  const ToothLoadPattern pattern = tooth_load_pattern(coupling, point, options);
  const int n = coupling.teeth();
  const double stiffness = coupling.mesh_stiffness_n_per_m();
  const double crown = coupling.crown_radius_m();
  const double half_face = 0.5 * coupling.facewidth_m();

  ToothContact c;
  c.total_normal_load_n = pattern.total_normal_load_n;      // eq 7
  c.mean_tooth_load_n = pattern.mean_tooth_load_n;          // eq 20
  c.max_separation_m = pattern.max_separation_m;            // eq 11
  c.load_sharing = pattern.load_sharing;                    // eqs 20-22
  c.peak_tooth_load_n = pattern.peak_tooth_load_n;          // eq 20
  c.elastic_deformation_m = pattern.elastic_deformation_m;  // eq 10
  c.offset_alpha_rad = pattern.offset_alpha_rad;            // eq 13
  c.max_contact_offset_m = pattern.max_contact_offset_m;    // eq 15
  c.z_axis_angle_rad = coupling.pressure_angle_rad() + point.direction_rad;

  c.teeth.resize(n);
  for (int j = 0; j < n; ++j) {
    ToothLoad& tooth = c.teeth[j];
    tooth.angle_rad = pattern.angle_rad(n, j);
    tooth.load_n = pattern.load_n(coupling, j);                                      // eq 9
    tooth.contact_offset_m = c.max_contact_offset_m * pattern.cos_theta(coupling, j);  // eq 16
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

  require_load_carried(pattern, c.sum_tooth_loads_n, point, options.min_load_fraction);
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
