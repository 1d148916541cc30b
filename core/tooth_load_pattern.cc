#include "core/tooth_load_pattern.h"

#include <sstream>

#include "core/model_error.h"
#include "core/tooth_contact.h"

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
  return coupling.root_crown_radius_m() * t * t / (2.0 * coupling.tan_pressure_angle());
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

}  // namespace

ToothLoadPattern tooth_load_pattern(const CouplingGeometry& coupling, const OperatingPoint& point,
                                    const ContactOptions& options) {
  validate_operating_point(coupling, point);
  validate_options(options);
  const int n = coupling.teeth();
  const double stiffness = coupling.mesh_stiffness_n_per_m();
  ToothLoadPattern p;
  p.total_normal_load_n =
      point.torque_nm / (coupling.pitch_radius_m() * coupling.cos_pressure_angle());  // eq 7
  p.mean_tooth_load_n = p.total_normal_load_n / n;                                   // eq 20
  p.max_separation_m =
      max_separation_m(coupling, point.misalignment_rad) + options.spacing_error_m;  // eq 11
  p.load_sharing = solve_load_sharing(p.mean_tooth_load_n, stiffness, p.max_separation_m,
                                      options.load_sharing);                         // 20-22
  p.peak_tooth_load_n = p.mean_tooth_load_n / p.load_sharing.q;                      // eq 20
  p.elastic_deformation_m = p.peak_tooth_load_n / stiffness;                         // eq 10
  p.offset_alpha_rad =
      offset_alpha_rad(p.load_sharing.q, n, options.continuous_quarter_sums);          // eq 13
  p.sin_misalignment = std::sin(point.misalignment_rad);  // one sincos with the cosine
  p.cos_misalignment = std::cos(point.misalignment_rad);
  p.max_contact_offset_m = coupling.crown_radius_m() * p.sin_misalignment;  // eq 15
  p.separation_ratio = p.max_separation_m / p.elastic_deformation_m;
  p.sin_alpha = std::sin(p.offset_alpha_rad);
  p.cos_alpha = std::cos(p.offset_alpha_rad);
  return p;
}

ToothLoadTotals tooth_load_totals(const CouplingGeometry& coupling, const ToothLoadPattern& pattern) {
  const int n = coupling.teeth();
  const double* const tooth_sin = coupling.tooth_sin().data();
  const double* const tooth_cos = coupling.tooth_cos().data();
  const double cos_alpha = pattern.cos_alpha, sin_alpha = pattern.sin_alpha;
  const double ratio = pattern.separation_ratio, peak = pattern.peak_tooth_load_n;
  ToothLoadTotals totals;
  // One pass, no branch on a tooth: the loaded teeth form arcs whose ends a branch predictor
  // misses when the point changes. The sum keeps tooth order (its bits; an unloaded tooth's +0
  // changes none): a chain of one addition per tooth, which the rest of the pass runs beside.
  // A tooth takes the maximum only from a smaller one, so the first of equal loads keeps it.
  int loaded = 0, max_tooth = 0;
  double max_load = 0.0, sum = 0.0;
  for (int j = 0; j < n; ++j) {
    const double s = tooth_sin[j] * cos_alpha + tooth_cos[j] * sin_alpha;
    const double share = 1.0 - ratio * s * s;
    const double load = peak * (share > 0.0 ? share : 0.0);  // a NaN share too: as load_n
    loaded += load > 0.0;
    sum += load;
    const bool larger = load > max_load;
    max_load = larger ? load : max_load;
    max_tooth = larger ? j : max_tooth;
  }
  totals.loaded_teeth = loaded;
  totals.max_load_tooth = max_tooth;
  totals.max_load_n = max_load;
  totals.sum_of_loads_n = sum;
  return totals;
}

ToothLoadPattern tooth_load_pattern(const ToothContact& contact) {
  ToothLoadPattern p;
  p.total_normal_load_n = contact.total_normal_load_n;
  p.mean_tooth_load_n = contact.mean_tooth_load_n;
  p.max_separation_m = contact.max_separation_m;
  p.load_sharing = contact.load_sharing;
  p.peak_tooth_load_n = contact.peak_tooth_load_n;
  p.elastic_deformation_m = contact.elastic_deformation_m;
  p.offset_alpha_rad = contact.offset_alpha_rad;
  p.max_contact_offset_m = contact.max_contact_offset_m;
  p.separation_ratio = p.max_separation_m / p.elastic_deformation_m;
  p.sin_alpha = std::sin(p.offset_alpha_rad);
  p.cos_alpha = std::cos(p.offset_alpha_rad);
  return p;
}

void require_load_carried(const ToothLoadPattern& pattern, double sum_of_loads_n, const OperatingPoint& point,
                          double minimum) {
  const double carried = sum_of_loads_n / pattern.total_normal_load_n;
  if (carried >= minimum) return;
  std::ostringstream allowed;
  allowed.precision(3);
  allowed << "a torque at which eq 9's tooth loads carry at least " << 100 * minimum
          << " % of P_t at this misalignment; they carry " << 100 * carried
          << " % (z_e/z_o = " << pattern.load_sharing.ze_over_zo
          << ", light torque near the jam angle is outside eq 22's range)";
  throw InvalidInput("operating_point.torque_nm", point.torque_nm, allowed.str());
}

bool loads_clearly_carried(const CouplingGeometry& coupling, const ToothLoadPattern& pattern, double minimum) {
  constexpr double kMargin = 1e-9;  // of P_t; the order moves the sum by ~N ulp (1e-14 for 100 teeth)
  const auto s = coupling.tooth_sin() * pattern.cos_alpha + coupling.tooth_cos() * pattern.sin_alpha;
  const auto share = 1.0 - pattern.separation_ratio * s * s;
  const double sum = pattern.peak_tooth_load_n * share.max(0.0).sum();  // one pass, no temporary
  return sum >= (minimum + kMargin) * pattern.total_normal_load_n;  // NaN: false
}

}  // namespace gc
