#include "core/stress.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/coupling_geometry.h"

namespace gc {
namespace {

// No stress is infinite safety, reported as the largest double (stress.h). A stress so small
// that the ratio overflows (a torque of 1e-306 N·m, found by fuzz/wire_request_fuzzer) is
// reported the same way, never as infinity.
double safety(double allowable_pa, double stress_pa) {
  constexpr double kLargest = std::numeric_limits<double>::max();
  return stress_pa > 0.0 ? std::min(allowable_pa / stress_pa, kLargest) : kLargest;
}

}  // namespace

ToothStress tooth_stress(const CouplingGeometry& coupling, double tooth_load_n,
                         double contact_length_m) {
  const CouplingDefinition& d = coupling.definition();
  ToothStress result;
  if (tooth_load_n <= 0.0) {
    result.contact_safety_factor = std::numeric_limits<double>::max();
    result.bending_safety_factor = std::numeric_limits<double>::max();
    return result;
  }
  // Hertz, cylinder (radius R_F) on a plane, both steel: E* = E / (2 (1 - nu^2)).
  const double e_star = d.youngs_modulus_pa / (2.0 * (1.0 - d.poisson_ratio * d.poisson_ratio));
  const double line_length = coupling.working_depth_m() / coupling.cos_pressure_angle();
  const double r = coupling.crown_radius_m();
  result.contact_stress_pa = std::sqrt(tooth_load_n * e_star / (M_PI * line_length * r));
  result.contact_half_width_m = std::sqrt(4.0 * tooth_load_n * r / (M_PI * line_length * e_star));
  // Lewis/AGMA: sigma = W_t / (F_e m Y), weaker member's Y, 45 deg dispersion to the root.
  const double tangential_load = tooth_load_n * coupling.cos_pressure_angle();
  const double tooth_height = 0.5 * (d.outer_diameter_m - d.root_diameter_m);
  const double loaded_face = std::min(d.facewidth_m, contact_length_m + 2.0 * tooth_height);
  const double form_factor = std::min(d.form_factor_hub, d.form_factor_sleeve);
  result.bending_stress_pa = tangential_load / (loaded_face * d.module_m * form_factor);
  result.contact_safety_factor = safety(d.allowables.contact_stress_pa, result.contact_stress_pa);
  result.bending_safety_factor = safety(d.allowables.bending_stress_pa, result.bending_stress_pa);
  return result;
}

}  // namespace gc
