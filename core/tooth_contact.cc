#include "core/tooth_contact.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/coupling_geometry.h"
#include "core/tooth_load_pattern.h"

namespace gc {
namespace {

// Eq 18: chord of the crown circle R_F cut at depth delta_d > 0 [m]. Each operation is monotone,
// so a larger load never gives a shorter chord, rounding included.
ToothBlock contact_length_m(double crown_radius_m, const ToothBlock& deformation_m) {
  const ToothBlock depth = deformation_m.min(crown_radius_m);
  return 2.0 * (crown_radius_m * crown_radius_m - (crown_radius_m - depth) * (crown_radius_m - depth)).sqrt();
}

double contact_length_m(double crown_radius_m, double deformation_m) {
  const double depth = std::min(deformation_m, crown_radius_m);
  return 2.0 * std::sqrt(crown_radius_m * crown_radius_m - (crown_radius_m - depth) * (crown_radius_m - depth));
}

// Eqs 9 and 16-19 for every tooth into `table` (N entries) and, as it goes, the totals of eq 9
// and whether a loaded tooth's zone reached a facewidth edge.
struct ListedTotals {
  ToothLoadTotals loads;
  bool edge_loaded = false;
  double governing_chord_m = 0.0;  ///< F_c of the most loaded tooth, eq 18 [m]
};

ListedTotals fill_teeth(const CouplingGeometry& coupling, const ToothLoadPattern& pattern, ToothLoad* table) {
  const int n = coupling.teeth();
  const double stiffness = coupling.mesh_stiffness_n_per_m();
  const double crown = coupling.crown_radius_m();
  const double half_face = 0.5 * coupling.facewidth_m();
  bool edge = false;  // in a local: the tooth table's stores could alias it
  // Eq 9 and eq 16 run over a block of teeth as arrays. The division of eq 17 and the root of
  // eq 18 cost most, so they run only over the loaded teeth of the block, gathered: an unloaded
  // tooth has no deformation and no zone. The totals are tooth_load_totals', as without the table.
  for (Eigen::Index first = 0; first < n; first += kToothBlock) {
    const Eigen::Index count = std::min<Eigen::Index>(kToothBlock, n - first);
    const ToothBlock load = pattern.load_n(pattern.sin_theta(coupling, first, count));  // eq 9
    const ToothBlock offset =
        pattern.max_contact_offset_m * pattern.cos_theta(coupling, first, count);  // eq 16
    ToothBlock loaded_load(count);
    std::array<Eigen::Index, kToothBlock> loaded_tooth;
    Eigen::Index loaded = 0;
    for (Eigen::Index i = 0; i < count; ++i) {
      loaded_load[loaded] = load[i];
      loaded_tooth[static_cast<std::size_t>(loaded)] = i;
      loaded += load[i] > 0.0;
    }
    const ToothBlock deformation = loaded_load.head(loaded) / stiffness;  // eq 17
    const ToothBlock length = contact_length_m(crown, deformation);       // eq 18
    const double* const base_angle = coupling.tooth_angle_rad().data() + first;
    Eigen::Index k = 0;  // the next loaded tooth
    for (Eigen::Index i = 0; i < count; ++i) {
      const Eigen::Index j = first + i;
      ToothLoad& tooth = table[j];
      tooth.angle_rad = base_angle[i] + pattern.offset_alpha_rad;
      tooth.load_n = load[i];
      tooth.contact_offset_m = offset[i];
      if (k < loaded && loaded_tooth[static_cast<std::size_t>(k)] == i) {
        const double begin = offset[i] - 0.5 * length[k];  // eq 19
        const double end = offset[i] + 0.5 * length[k];
        tooth.deformation_m = deformation[k];
        tooth.contact_length_m = length[k];
        tooth.zone_begin_m = std::clamp(begin, -half_face, half_face);
        tooth.zone_end_m = std::clamp(end, -half_face, half_face);
        edge = edge || begin < -half_face || end > half_face;
        ++k;
      } else {
        tooth.deformation_m = 0.0;
        tooth.contact_length_m = 0.0;
        // Eq 19 with F_c = 0; + 0.0 turns an offset of -0 (no misalignment) into +0, as there.
        tooth.zone_begin_m = std::clamp(offset[i], -half_face, half_face);
        tooth.zone_end_m = std::clamp(offset[i] + 0.0, -half_face, half_face);
      }
    }
  }
  const ToothLoadTotals totals = tooth_load_totals(coupling, pattern);
  return {totals, edge, table[totals.max_load_tooth].contact_length_m};
}

// Whether some loaded tooth's eq 19 zone reaches past a facewidth edge, without the table. Every
// |F_d| <= F_i (eq 16) and every F_c <= the most loaded tooth's (eq 18 grows with P_d), so when
// F_i plus half that chord stays inside F/2 (with a margin far above the rounding of eq 19) no
// zone can, and no tooth is visited: the usual case. Otherwise each loaded tooth's zone is
// computed as fill_teeth() does.
bool zone_reaches_an_edge(const CouplingGeometry& coupling, const ToothLoadPattern& pattern,
                          double widest_chord_m) {
  const double stiffness = coupling.mesh_stiffness_n_per_m();
  const double crown = coupling.crown_radius_m();
  const double half_face = 0.5 * coupling.facewidth_m();
  if ((pattern.max_contact_offset_m + 0.5 * widest_chord_m) * (1.0 + 1e-9) < half_face) return false;
  const int n = coupling.teeth();
  for (Eigen::Index first = 0; first < n; first += kToothBlock) {
    const Eigen::Index count = std::min<Eigen::Index>(kToothBlock, n - first);
    const ToothBlock load = pattern.load_n(pattern.sin_theta(coupling, first, count));  // eq 9
    const ToothBlock offset = pattern.max_contact_offset_m * pattern.cos_theta(coupling, first, count);
    const ToothBlock length = contact_length_m(crown, ToothBlock(load / stiffness));  // 17-18
    for (Eigen::Index i = 0; i < count; ++i) {
      if (load[i] > 0.0 && (offset[i] - 0.5 * length[i] < -half_face ||
                            offset[i] + 0.5 * length[i] > half_face)) {
        return true;
      }
    }
  }
  return false;
}

// Every member of `c` but the table: eqs 7-15 and 20-22 from the pattern, the totals of eq 9,
// the refusal of a point whose loads miss P_t, and the stress of the most loaded tooth.
void set_members(const CouplingGeometry& coupling, const OperatingPoint& point,
                 const ContactOptions& options, const ToothLoadPattern& pattern,
                 const ListedTotals& totals, ToothContact& c) {
  c.total_normal_load_n = pattern.total_normal_load_n;      // eq 7
  c.mean_tooth_load_n = pattern.mean_tooth_load_n;          // eq 20
  c.max_separation_m = pattern.max_separation_m;            // eq 11
  c.load_sharing = pattern.load_sharing;                    // eqs 20-22
  c.peak_tooth_load_n = pattern.peak_tooth_load_n;          // eq 20
  c.elastic_deformation_m = pattern.elastic_deformation_m;  // eq 10
  c.offset_alpha_rad = pattern.offset_alpha_rad;            // eq 13
  c.max_contact_offset_m = pattern.max_contact_offset_m;    // eq 15
  c.z_axis_angle_rad = coupling.pressure_angle_rad() + point.direction_rad;
  c.teeth_in_contact = totals.loads.loaded_teeth;
  c.max_load_tooth = totals.loads.max_load_tooth;
  c.max_tooth_load_n = totals.loads.max_load_n;
  c.sum_tooth_loads_n = totals.loads.sum_of_loads_n;
  c.edge_loaded = totals.edge_loaded;
  require_load_carried(pattern, c.sum_tooth_loads_n, point, options.min_load_fraction);
  c.slices = options.slices;
  c.continuous_quarter_sums = options.continuous_quarter_sums;
  c.max_stress = tooth_stress(coupling, c.max_tooth_load_n, totals.governing_chord_m);  // it governs
}

// On a throw `c` holds no result: its members back to their defaults, the table's storage kept.
void discard(ToothContact& c) {
  std::vector<ToothLoad> teeth = std::move(c.teeth);
  teeth.clear();
  c = ToothContact{};
  c.teeth = std::move(teeth);
}

}  // namespace

// set_members() writes every member but the table, so `c` is not first reset (a zeroed
// temporary of its 200 bytes was a tenth of an evaluation without the table).
void tooth_contact(const CouplingGeometry& coupling, const OperatingPoint& point,
                   const ContactOptions& options, ToothContact& c) {
  try {
    const ToothLoadPattern pattern = tooth_load_pattern(coupling, point, options);
    c.teeth.resize(static_cast<std::size_t>(coupling.teeth()));
    const ListedTotals totals = fill_teeth(coupling, pattern, c.teeth.data());
    set_members(coupling, point, options, pattern, totals, c);
  } catch (...) {
    discard(c);
    throw;
  }
}

ToothLoadPattern tooth_contact_without_teeth(const CouplingGeometry& coupling, const OperatingPoint& point,
                                             const ContactOptions& options, ToothContact& c) {
  c.teeth.clear();  // its storage is kept for list_teeth()
  try {
    const ToothLoadPattern pattern = tooth_load_pattern(coupling, point, options);
    ListedTotals totals;
    totals.loads = tooth_load_totals(coupling, pattern);  // eq 9
    // Eqs 17-18 for the most loaded tooth alone (no tooth loaded: no chord).
    totals.governing_chord_m = contact_length_m(
        coupling.crown_radius_m(), totals.loads.max_load_n / coupling.mesh_stiffness_n_per_m());
    totals.edge_loaded = zone_reaches_an_edge(coupling, pattern, totals.governing_chord_m);
    set_members(coupling, point, options, pattern, totals, c);
    return pattern;
  } catch (...) {
    discard(c);
    throw;
  }
}

void list_teeth(const CouplingGeometry& coupling, ToothContact& c) {
  c.teeth.resize(static_cast<std::size_t>(coupling.teeth()));
  fill_teeth(coupling, tooth_load_pattern(c), c.teeth.data());
}

ToothContact tooth_contact(const CouplingGeometry& coupling, const OperatingPoint& point,
                           const ContactOptions& options) {
  ToothContact contact;
  tooth_contact(coupling, point, options, contact);
  return contact;
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
