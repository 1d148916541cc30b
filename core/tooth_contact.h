// Tooth contact of a misaligned crowned-tooth coupling (Section 4.1): load sharing, the normal
// load on every tooth and facewidth slice, contact zones, deformation, stress.
//
// Frame: tooth j sits at angle theta_j = 2 pi j / N + alpha from the z'' axis, which passes
// through the most loaded tooth and is rotated from the misalignment axis by the pressure angle
// (Figure 3b); z'' lies at phi + beta from z' (eqs 44-45).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/load_sharing.h"
#include "core/operating_point.h"
#include "core/stress.h"
#include "core/tooth_load_pattern.h"

namespace gc {

class CouplingGeometry;

struct ContactOptions {
  LoadSharingOptions load_sharing;  ///< eqs 20-22
  int slices = 20;                  ///< N_s, even, slices across each contact zone (eq 14)
  /// Tooth spacing error [m], added to the maximum separation z_o of eq 11. Zero in the
  /// paper's model (equally spaced teeth, Section 4); the spacing_errors effect sets it
  /// (Section 6.4, docs/effects.md).
  double spacing_error_m = 0.0;
  /// Least share of P_t the eq 9 tooth loads must carry [-]. Below z_e/z_o of about 0.03
  /// (light torque near the jam angle) eq 9 with eq 22's q loses load, down to none at all;
  /// such a point is an InvalidInput on the torque, not a result (docs/model.md).
  double min_load_fraction = 0.9;
  /// false: the paper's eqs 13 and 42-43, whose int(qN/4) and residue of qN make |M| a
  /// sawtooth in torque and misalignment. true: the continuous variant of docs/model.md
  /// (issue 8): eq 13's residue folded, min(r, 1 - r), and the quarter sums closed by the
  /// fractional tooth, weighted by the fractional part of qN/4. Equal to the paper's form
  /// wherever qN/4 is a whole number.
  bool continuous_quarter_sums = false;
};

/// One tooth of the hub.
struct ToothLoad {
  double angle_rad = 0.0;           ///< theta_j = 2 pi j / N + alpha, from the z'' axis [rad]
  double load_n = 0.0;              ///< P_d, eq 9 (clipped at zero) [N]
  double contact_offset_m = 0.0;    ///< F_d, eq 16: contact centre from the flank centre [m]
  double deformation_m = 0.0;       ///< delta_d = P_d / C, eq 17 [m]
  double contact_length_m = 0.0;    ///< F_c, eq 18 [m]
  double zone_begin_m = 0.0;        ///< eq 19 lower bound, clipped to -F/2 [m]
  double zone_end_m = 0.0;          ///< eq 19 upper bound, clipped to +F/2 [m]
  bool in_contact() const { return load_n > 0.0; }
};

struct ToothContact {
  LoadSharing load_sharing;             ///< q and its iteration, eqs 20-22
  double total_normal_load_n = 0.0;     ///< P_t = T / (R cos phi), eq 7 [N]
  double mean_tooth_load_n = 0.0;       ///< P_t' = P_t / N, eq 20 [N]
  double peak_tooth_load_n = 0.0;       ///< P_i = P_t' / q, eq 20 [N]
  double elastic_deformation_m = 0.0;   ///< z_e = P_i / C, eq 10 [m]
  double max_separation_m = 0.0;        ///< z_o, eq 11 [m]
  double offset_alpha_rad = 0.0;        ///< alpha, eq 13 (residue as an angle) [rad]
  double max_contact_offset_m = 0.0;    ///< F_i = R_F sin(zeta), eq 15 [m]
  double z_axis_angle_rad = 0.0;        ///< phi + beta: z'' from z' [rad]
  std::vector<ToothLoad> teeth;         ///< j = 0 .. N-1; empty from tooth_contact_without_teeth()
  int teeth_in_contact = 0;             ///< count of P_d > 0
  int max_load_tooth = 0;               ///< j of the largest P_d
  double max_tooth_load_n = 0.0;        ///< largest P_d [N]
  double sum_tooth_loads_n = 0.0;       ///< sum of P_d, against P_t [N]
  bool edge_loaded = false;             ///< some eq 19 zone reached a facewidth edge
  int slices = 0;                       ///< N_s, eq 14
  bool continuous_quarter_sums = false; ///< ContactOptions' choice, read by eqs 42-43
  ToothStress max_stress;               ///< stress of the most loaded tooth (it governs)

  /// cos(pi l / N_s), l = -N_s/2 .. N_s/2, eq 14 (computed on demand: only outputs need it).
  Eigen::VectorXd slice_weights() const;

  /// Eq 14: load on every slice, P_ds = P_d cos(pi l / N_s): row j, column l + N_s/2 [N].
  /// From the table of teeth (no rows for a contact without it: list_teeth() adds it).
  Eigen::MatrixXd slice_loads() const;
  /// Facewidth position of slice l of tooth j: F_d + (l / N_s) F_c, from the flank centre [m].
  /// From the table of teeth, as slice_loads().
  double slice_position_m(int tooth, int slice) const;
};

/// Eqs 5-22 for `point` (friction is not used here). Validates the operating point (throws
/// InvalidInput naming the field), rejects points where the tooth loads carry less than
/// options.min_load_fraction of P_t, and throws NotConverged when eqs 20-22 do not converge.
ToothContact tooth_contact(const CouplingGeometry& coupling, const OperatingPoint& point,
                           const ContactOptions& options = {});

/// The same into `contact`, reusing its tooth table's storage: a caller evaluating many points
/// keeps one ToothContact and allocates nothing once it holds N teeth. Every member is
/// overwritten; on a throw `contact` holds no result.
void tooth_contact(const CouplingGeometry& coupling, const OperatingPoint& point,
                   const ContactOptions& options, ToothContact& contact);

/// Eqs 5-22 without listing the teeth: every member of ToothContact but `teeth`, which is left
/// empty (its storage kept), bit for bit tooth_contact()'s, with the same errors. Every tooth
/// follows in closed form from the members (eq 9 from P_i, z_o / z_e and alpha; eqs 16-19 from
/// F_i, C and R_F), so the count, the largest load, the sum of P_d, edge_loaded and the stress
/// need no table: what a load case, a batch or induced_moments() reads, at a fraction of the
/// cost of 7 numbers for each of N teeth. list_teeth() adds the table when an output needs it.
/// Returns the eq 9 pattern the teeth follow from, with zeta's sine and cosine (eqs 15, 37).
ToothLoadPattern tooth_contact_without_teeth(const CouplingGeometry& coupling, const OperatingPoint& point,
                                             const ContactOptions& options, ToothContact& contact);

/// Eqs 9 and 16-19 for every tooth of `contact`, solved for `coupling`: fills contact.teeth as
/// tooth_contact() does (bit for bit), reusing its storage.
void list_teeth(const CouplingGeometry& coupling, ToothContact& contact);

}  // namespace gc
