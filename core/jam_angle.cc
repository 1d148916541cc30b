#include "core/jam_angle.h"

#include <cmath>
#include <limits>

#include "core/bracketed_root.h"
#include "core/model_error.h"

namespace gc {
namespace {

constexpr double kRootTolerance = 1e-14;  // [rad]

void validate(const JamGeometry& g) {
  require_positive("coupling.facewidth_m", g.facewidth_m);
  require_positive("coupling.backlash_m", g.backlash_m);
  require_positive("coupling.tooth_thickness_m", g.hub_tooth_m);
  require_in_range("coupling.pressure_angle_rad", g.pressure_angle_rad, 1e-3, M_PI / 4);
  if (!std::isfinite(g.crown_radius_m) || g.crown_radius_m <= 0.5 * g.facewidth_m) {
    throw InvalidInput("coupling.crown_radius_m", g.crown_radius_m,
                       "a finite value > F/2 = " + format_number(0.5 * g.facewidth_m) + " m");
  }
}

// Eq 30: the half contact f_c = 2 R_F sin(xi/2) of eq 24 is read with its paper approximation
// f_c ~ R_F sin(xi); the contact leaves the facewidth at sin(xi) = F / (2 R_F).
double facewidth_limit_rad(const JamGeometry& g) {
  return std::asin(g.facewidth_m / (2.0 * g.crown_radius_m));
}

}  // namespace

std::string_view to_string(JamCriterion criterion) {
  switch (criterion) {
    case JamCriterion::kBothFlanks: return "both_flanks";
    case JamCriterion::kFacewidth: return "facewidth";
    case JamCriterion::kRadial: return "radial";
  }
  return "unknown";
}

double both_flanks_residual_m(const JamGeometry& g, double xi) {
  const double f_c = 2.0 * g.crown_radius_m * std::sin(0.5 * xi);                    // eq 24
  const double t_star = g.hub_tooth_m - 2.0 * g.crown_radius_m * (1.0 - std::cos(xi));  // eq 25
  const double sin_phi = std::sin(g.pressure_angle_rad);
  const double s_star = g.sleeve_space_m - g.facewidth_m * std::sin(xi) * sin_phi * sin_phi;  // 26
  return 2.0 * f_c * std::sin(xi) + t_star / std::cos(xi) - s_star;                   // eq 23
}

JamAngle jam_angle(const JamGeometry& g) {
  validate(g);
  JamAngle result;
  result.facewidth_rad = facewidth_limit_rad(g);
  // Eq 34, with eq 33's "S_c2 - t_c2" read as the backlash S_c2 - t_c1 (docs/model.md).
  const double radial_sine = g.backlash_m / (g.facewidth_m * std::sin(g.pressure_angle_rad));
  result.radial_rad = radial_sine >= 1.0 ? M_PI / 2 : std::asin(radial_sine);
  // Eq 28 holds while f_c < F/2, i.e. below the facewidth limit: bracket the root there. The
  // residual is -b < 0 at xi = 0 and grows with xi.
  const auto residual = [&g](double xi) { return both_flanks_residual_m(g, xi); };
  result.both_flanks_rad =
      find_bracketed_root(residual, 0.0, result.facewidth_rad, kRootTolerance);

  result.angle_rad = result.facewidth_rad;
  result.governing = JamCriterion::kFacewidth;
  if (result.both_flanks_rad && *result.both_flanks_rad <= result.angle_rad) {
    result.angle_rad = *result.both_flanks_rad;
    result.governing = JamCriterion::kBothFlanks;
  }
  if (result.radial_rad < result.angle_rad) {
    result.angle_rad = result.radial_rad;
    result.governing = JamCriterion::kRadial;
  }
  return result;
}

double crown_radius_for_both_flanks_jam(JamGeometry g, double xi_rad) {
  require_in_range("jam_angle_rad", xi_rad, 1e-6, 0.5);
  const double lo = 0.5 * g.facewidth_m * (1.0 + 1e-9);
  const double hi = 1000.0;
  const auto residual = [&g, xi_rad](double crown_radius_m) {
    g.crown_radius_m = crown_radius_m;
    return both_flanks_residual_m(g, xi_rad);
  };
  const auto root = find_bracketed_root(residual, lo, hi, 1e-12);
  if (!root) {
    throw InvalidInput("jam_angle_rad", xi_rad,
                       "an angle eq 23 reaches for some crown radius in (F/2, 1000 m)");
  }
  return *root;
}

}  // namespace gc
