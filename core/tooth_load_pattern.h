// Eq 9's tooth load pattern before any tooth is listed: the scalars of Section 4.1 (eqs 7,
// 10-13, 15, 20-22) and, from them, the load P_d of any tooth. tooth_contact() lists every tooth
// with its contact zone and the stress; a model prediction needs only the loads that eqs 42-43
// sum and their total, so it reads them here without a tooth table per sample (the diagnosis
// predicts millions of samples, docs/benchmarks.md "Diagnose").
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "core/coupling_geometry.h"
#include "core/load_sharing.h"
#include "core/operating_point.h"

namespace gc {

struct ContactOptions;
struct ToothContact;

/// Teeth evaluated at once as arrays: a block lives on the stack (an evaluation allocates
/// nothing) and is long enough for the vector units, short enough to stay in L1 beside the
/// tooth table it fills.
inline constexpr int kToothBlock = 32;
using ToothBlock = Eigen::Array<double, Eigen::Dynamic, 1, Eigen::ColMajor, kToothBlock, 1>;

struct ToothLoadPattern {
  double total_normal_load_n = 0.0;     ///< P_t = T / (R cos phi), eq 7 [N]
  double mean_tooth_load_n = 0.0;       ///< P_t' = P_t / N, eq 20 [N]
  double max_separation_m = 0.0;        ///< z_o, eq 11, plus the spacing error [m]
  LoadSharing load_sharing;             ///< q and its iteration, eqs 20-22
  double peak_tooth_load_n = 0.0;       ///< P_i = P_t' / q, eq 20 [N]
  double elastic_deformation_m = 0.0;   ///< z_e = P_i / C, eq 10 [m]
  double offset_alpha_rad = 0.0;        ///< alpha, eq 13 [rad]
  double max_contact_offset_m = 0.0;    ///< F_i = R_F sin(zeta), eq 15 [m]
  double separation_ratio = 0.0;        ///< z_o / z_e of eq 9 [-]
  double sin_alpha = 0.0;
  double cos_alpha = 1.0;
  /// sin and cos of the misalignment zeta, for eq 15 and eq 37. tooth_load_pattern(contact)
  /// leaves them at 0 and 1: a contact does not hold zeta (induced_moments() sets them).
  double sin_misalignment = 0.0;
  double cos_misalignment = 1.0;

  /// sin and cos of theta_j = 2 pi j / N + alpha by the angle-sum rule on the coupling's tooth
  /// table, for one tooth and for the block of `count` teeth from `first`. The block forms
  /// are the same operations lane by lane, so both give the same bits.
  double sin_theta(const CouplingGeometry& coupling, int j) const {
    return coupling.tooth_sin()[j] * cos_alpha + coupling.tooth_cos()[j] * sin_alpha;
  }
  double cos_theta(const CouplingGeometry& coupling, int j) const {
    return coupling.tooth_cos()[j] * cos_alpha - coupling.tooth_sin()[j] * sin_alpha;
  }
  ToothBlock sin_theta(const CouplingGeometry& coupling, Eigen::Index first, Eigen::Index count) const {
    return coupling.tooth_sin().segment(first, count) * cos_alpha +
           coupling.tooth_cos().segment(first, count) * sin_alpha;
  }
  ToothBlock cos_theta(const CouplingGeometry& coupling, Eigen::Index first, Eigen::Index count) const {
    return coupling.tooth_cos().segment(first, count) * cos_alpha -
           coupling.tooth_sin().segment(first, count) * sin_alpha;
  }
  /// Eq 9 as read: P_d = P_i [1 - (z_o / z_e) sin^2(theta_j)], clipped at zero [N].
  double load_n(const CouplingGeometry& coupling, int j) const {
    const double s = sin_theta(coupling, j);
    return peak_tooth_load_n * std::max(0.0, 1.0 - separation_ratio * s * s);
  }
  /// As std::max(0.0, x) above, a NaN share (0 / 0: a torque so small that z_e underflows, with
  /// no misalignment) gives no load; Eigen's max would keep the NaN.
  ToothBlock load_n(const ToothBlock& sin_theta) const {
    const ToothBlock share = 1.0 - separation_ratio * sin_theta * sin_theta;
    return peak_tooth_load_n * (share > 0.0).select(share, 0.0);
  }
};

/// Eq 9 summed over the teeth: what tooth_contact() reports of the loads without listing them.
struct ToothLoadTotals {
  int loaded_teeth = 0;        ///< count of P_d > 0
  int max_load_tooth = 0;      ///< j of the largest P_d, the first if several (0 if none)
  double max_load_n = 0.0;     ///< largest P_d [N]
  double sum_of_loads_n = 0.0; ///< sum of P_d, sum_of_tooth_loads_n [N]
};

/// The totals of eq 9 over every tooth of `coupling` without a pass over the teeth: the loaded
/// teeth are two runs, about theta = 0 and pi, whose ends are found from their half-width and
/// checked with ToothLoadPattern::load_n's own operations (the count is the tooth table's, bit for
/// bit its test), the largest load is one of the three teeth nearest either, and the sum is
/// sum_of_tooth_loads_n. A pass over 100 teeth with a chain of additions was 40 % of a load case.
ToothLoadTotals tooth_load_totals(const CouplingGeometry& coupling, const ToothLoadPattern& pattern);

/// Eq 9's loads summed in closed form: 1 - r sin^2 theta = (1 - r/2) + (r/2) cos 2 theta, and the
/// cosines of the carrying teeth, a run of even steps, sum as a geometric series. Within a few ulp
/// per tooth of the sum in tooth order (a tooth at a run's end carries next to nothing, wherever
/// rounding puts it). In tooth order for a NaN or infinite ratio z_o / z_e [N].
double sum_of_tooth_loads_n(const CouplingGeometry& coupling, const ToothLoadPattern& pattern);

/// The pattern at `point`. Validates the operating point and the options (throws InvalidInput
/// naming the field) and throws NotConverged when eqs 20-22 do not converge.
ToothLoadPattern tooth_load_pattern(const CouplingGeometry& coupling, const OperatingPoint& point,
                                    const ContactOptions& options);

/// The pattern a solved contact's teeth follow from (its members; sin and cos of alpha again;
/// not zeta's, see above),
/// bit for bit the one tooth_contact() solved: what list_teeth() and the quarter sums of
/// induced_moments() read, with or without the contact's tooth table.
ToothLoadPattern tooth_load_pattern(const ToothContact& contact);

/// Rejects a pattern whose tooth loads, summing to `sum_of_loads_n`, carry less than `minimum` of
/// P_t: eq 22 is a fitted curve, and far below its range (light torque near the jam angle) eq 9
/// with that q no longer carries the transmitted load. Throws InvalidInput on the torque.
void require_load_carried(const ToothLoadPattern& pattern, double sum_of_loads_n, const OperatingPoint& point,
                          double minimum);

}  // namespace gc
