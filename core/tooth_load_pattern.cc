#include "core/tooth_load_pattern.h"

#include <cmath>
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

// Eq 9's shares summed over the teeth, sum_j max(0, 1 - r sin^2 theta_j) with theta_j = 2 pi j / N
// + alpha, in closed form: no pass over the teeth. 1 - r sin^2 theta = A + B cos 2 theta (A = 1 -
// r/2, B = r/2). With r <= 1 every tooth carries, and the cosines of 2 theta_j, even steps round the
// circle, sum to zero (N >= 3). Otherwise a tooth carries where cos 2 theta > -A/B, within beta of
// 2 theta = 0: the angles 2 theta_j are g = gcd(2, N) copies of M = N / g even steps from 2 alpha,
// so the carrying ones are a run of consecutive steps, whose cosines sum as a geometric series.
// A tooth on the run's edge carries next to nothing, so where rounding puts it moves the sum by
// next to nothing.
double load_share_sum(int teeth, double alpha, double r) {
  if (r <= 1.0) return teeth * (1.0 - 0.5 * r);
  const int copies = teeth % 2 == 0 ? 2 : 1;
  const double step = 2.0 * M_PI / (teeth / copies);  // between neighbouring 2 theta [rad]
  const double beta = std::acos(1.0 - 2.0 / r);        // the carrying arc's half-width [rad]
  const double centre = -2.0 * alpha / step, half = beta / step;  // in steps
  const double first = std::floor(centre - half) + 1.0, last = std::ceil(centre + half) - 1.0;
  const double count = last - first + 1.0;
  if (count <= 0.0) return 0.0;
  const double cosines = std::sin(0.5 * count * step) / std::sin(0.5 * step) *
                         std::cos(2.0 * alpha + step * (first + 0.5 * (count - 1.0)));
  return copies * (count * (1.0 - 0.5 * r) + 0.5 * r * cosines);
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
  constexpr double kMargin = 1e-9;  // of P_t; the closed form and tooth order differ by ~N ulp (1e-14 for 100 teeth)
  const double r = pattern.separation_ratio;
  if (!(r >= 0.0) || !std::isfinite(r)) return false;  // the sum in tooth order says what a NaN share gives
  const double sum = pattern.peak_tooth_load_n * load_share_sum(coupling.teeth(), pattern.offset_alpha_rad, r);
  return sum >= (minimum + kMargin) * pattern.total_normal_load_n;  // NaN: false
}

}  // namespace gc
