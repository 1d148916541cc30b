#include "core/tooth_load_pattern.h"

#include <algorithm>
#include <array>
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

namespace {

// z_o / z_e is NaN (0 / 0: a torque so small that z_e underflows, with no misalignment) or infinite
// (z_e underflows beside a misalignment): eq 9's share 1 - r sin^2 theta is then NaN or -inf on
// every tooth (NaN where sin theta = 0), which load_n clips to no load.
bool no_tooth_carries(const ToothLoadPattern& pattern) { return !std::isfinite(pattern.separation_ratio); }

// The teeth of eq 9 about one of the two angles where sin(theta) = 0, as whole tooth numbers j
// (taken modulo N): theta_j = 2 pi j / N + alpha is `centre` (0 or pi) at the real j = c, and the
// teeth this arc owns are those within a quarter turn before or after it, [c - N/4, c + N/4).
// Within them sin^2(theta) grows with the distance from c, so the loaded teeth (P_d > 0, eq 9's
// 1 - r sin^2 theta > 0) are one run about the tooth nearest c: its ends are estimated from the
// arc's half-width and then moved tooth by tooth to where P_d, computed as the tooth table
// computes it, turns to zero. A tooth beside the estimate is usually the end: a few teeth are
// evaluated, not N.
class ToothArc {
 public:
  /// The arc about the real tooth number `centre`, owning the teeth first_owned .. last_owned,
  /// loaded within `half_width` teeth of the centre.
  ToothArc(const CouplingGeometry& coupling, const ToothLoadPattern& pattern, double centre, long first_owned,
           long last_owned, double half_width)
      : coupling_(coupling), pattern_(pattern), n_(coupling.teeth()), c_(centre), first_owned_(first_owned),
        last_owned_(last_owned), nearest_(std::clamp(std::lround(centre), first_owned, last_owned)),
        half_width_(half_width) {}

  /// The two arcs, about theta = 0 and pi, owning every tooth once: their split is found once
  /// from the first centre (the second's, computed apart, could round a tooth at 90 deg both ways).
  static std::array<ToothArc, 2> both(const CouplingGeometry& coupling, const ToothLoadPattern& pattern) {
    const long n = coupling.teeth();
    // alpha is within a tooth pitch of 0 (eq 13): the arcs' teeth are within a turn of 0 .. N - 1.
    const double c = -pattern.offset_alpha_rad * n / (2.0 * M_PI);
    const long first = static_cast<long>(std::ceil(c - 0.25 * n));
    const long split = static_cast<long>(std::ceil(c + 0.25 * n));
    // Loaded where |sin theta| < 1 / sqrt(r): within asin(1 / sqrt(r)) of either centre.
    const double r = pattern.separation_ratio;
    const double half_width = (r > 1.0 ? std::asin(1.0 / std::sqrt(r)) : 0.5 * M_PI) * n / (2.0 * M_PI);
    return {ToothArc(coupling, pattern, c, first, split - 1, half_width),
            ToothArc(coupling, pattern, c + 0.5 * n, split, first + n - 1, half_width)};
  }

  /// Tooth j (any whole number) as its number in 0 .. N - 1; within a turn, without a division.
  int tooth(long j) const {
    if (j >= -n_ && j < 2 * n_) return static_cast<int>(j < 0 ? j + n_ : j >= n_ ? j - n_ : j);
    const long k = j % n_;
    return static_cast<int>(k < 0 ? k + n_ : k);
  }

  /// P_d of tooth j.
  double load_n(long j) const { return pattern_.load_n(coupling_, tooth(j)); }
  bool loaded(long j) const { return load_n(j) > 0.0; }

  /// The tooth nearest the centre and its neighbours: the largest P_d is one of them.
  std::array<long, 3> nearest() const { return {nearest_ - 1, nearest_, nearest_ + 1}; }

  /// How many of the arc's teeth carry load.
  int loaded_teeth() const {
    long seed = nearest_;
    if (!loaded(seed)) {  // twins equally near within rounding: either may carry the other's share
      if (seed - 1 >= first_owned_ && loaded(seed - 1)) --seed;
      else if (seed + 1 <= last_owned_ && loaded(seed + 1)) ++seed;
      else return 0;
    }
    long first = std::clamp(static_cast<long>(std::ceil(c_ - half_width_)), first_owned_, seed);
    while (first > first_owned_ && loaded(first - 1)) --first;
    while (!loaded(first)) ++first;  // stops at seed
    long last = std::clamp(static_cast<long>(std::floor(c_ + half_width_)), seed, last_owned_);
    while (last < last_owned_ && loaded(last + 1)) ++last;
    while (!loaded(last)) --last;
    return static_cast<int>(last - first + 1);
  }

 private:
  const CouplingGeometry& coupling_;
  const ToothLoadPattern& pattern_;
  long n_;
  double c_;                   ///< the centre, in teeth
  long first_owned_, last_owned_, nearest_;
  double half_width_;          ///< in teeth
};

}  // namespace

ToothLoadTotals tooth_load_totals(const CouplingGeometry& coupling, const ToothLoadPattern& pattern) {
  ToothLoadTotals totals;
  if (no_tooth_carries(pattern)) return totals;
  const std::array<ToothArc, 2> arcs = ToothArc::both(coupling, pattern);
  // The largest P_d, and the first tooth j in 0 .. N - 1 of equal ones (tooth 0 when none carries).
  for (const ToothArc& arc : arcs) {
    totals.loaded_teeth += arc.loaded_teeth();
    for (const long j : arc.nearest()) {
      const int tooth = arc.tooth(j);
      const double load = arc.load_n(j);
      if (load > totals.max_load_n || (load == totals.max_load_n && load > 0.0 && tooth < totals.max_load_tooth)) {
        totals.max_load_n = load;
        totals.max_load_tooth = tooth;
      }
    }
  }
  totals.sum_of_loads_n = sum_of_tooth_loads_n(coupling, pattern);
  return totals;
}

double sum_of_tooth_loads_n(const CouplingGeometry& coupling, const ToothLoadPattern& pattern) {
  if (no_tooth_carries(pattern)) return 0.0;
  return pattern.peak_tooth_load_n * load_share_sum(coupling.teeth(), pattern.offset_alpha_rad, pattern.separation_ratio);
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

}  // namespace gc
