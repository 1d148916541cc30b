// Jam angle of a crowned-tooth gear coupling (Section 4.2): the largest misalignment it takes
// before a hub tooth touches both sleeve flanks (eqs 23-29), its contact runs off the facewidth
// (eq 30) or the hub runs out of radial travel (eqs 31-34). Eq 35 takes the smallest.
#pragma once

#include <optional>
#include <string_view>

namespace gc {

enum class JamCriterion {
  kBothFlanks,  ///< eqs 23-29: the tooth spans the sleeve space width
  kFacewidth,   ///< eq 30: the contact reaches the facewidth edge
  kRadial,      ///< eqs 31-34: the radial travel uses up the backlash
};

std::string_view to_string(JamCriterion criterion);

/// The tooth-space geometry eq 23 reads, all lengths in metres.
struct JamGeometry {
  double crown_radius_m;        ///< R_F
  double hub_tooth_m;           ///< t_c1
  double sleeve_space_m;        ///< S_c2 = pi/P - t_c2 (eq 27) = t_c1 + b
  double facewidth_m;           ///< F
  double pressure_angle_rad;    ///< phi
  double backlash_m;            ///< b = S_c2 - t_c1 (eqs 33-34 as read, docs/model.md)
};

/// Result of eqs 23-35.
struct JamAngle {
  double angle_rad = 0.0;                 ///< xi, the governing (smallest) criterion [rad]
  JamCriterion governing = JamCriterion::kBothFlanks;
  /// eq 29: root of eq 23 [rad]; empty when no root lies below the facewidth limit (eq 28 is
  /// valid only while f_c < F/2, so the facewidth criterion governs there).
  std::optional<double> both_flanks_rad;
  double facewidth_rad = 0.0;             ///< eq 30 [rad]
  double radial_rad = 0.0;                ///< eq 34 [rad]
};

/// Residual of eq 23 at misalignment xi [m]: 2 f_c sin(xi) + t*_c1 / cos(xi) - S*_c2, with
/// f_c, t*_c1 and S*_c2 from eqs 24-26. Negative while the tooth still fits its space.
double both_flanks_residual_m(const JamGeometry& geometry, double xi_rad);

/// Eqs 23-35. Eq 23 is solved in its full trigonometric form with a bracketed root finder
/// (bisection refined by the secant rule, to 1e-14 rad). Throws InvalidInput for a geometry
/// with no clearance (b <= 0) or a crown radius no larger than F/2.
JamAngle jam_angle(const JamGeometry& geometry);

/// Inverse problem for docs/model.md's Table 3 comparison: the crown radius R_F [m] at which
/// eq 23 alone gives the jam angle `xi_rad`. Throws InvalidInput when no R_F in (F/2, 1 km)
/// does.
double crown_radius_for_both_flanks_jam(JamGeometry geometry, double xi_rad);

}  // namespace gc
