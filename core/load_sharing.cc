#include "core/load_sharing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/model_error.h"

namespace gc {

double load_sharing_ratio(double x) {
  if (std::isinf(x)) return 1.0;
  if (x < 0.4) return std::sqrt(1.195 + 1.75 * x - x * x) - 1.033;
  if (x < 1.0) return 0.36 * x + 0.14;
  return 1.0 - 1.0 / (2.0 * x);
}

namespace {

// The ranges bound the work of one solve (max_iterations) and keep the tolerance meaningful:
// a tolerance above 1e-3 would accept a q far from eq 22's and blame the torque for the tooth
// loads that do not add up (issue 9).
void validate(const LoadSharingOptions& options) {
  require_in_range("options.load_sharing.tolerance", options.tolerance, kMinLoadSharingTolerance,
                   kMaxLoadSharingTolerance);
  if (options.max_iterations < 1 || options.max_iterations > kMaxLoadSharingIterations) {
    throw InvalidInput("options.load_sharing.max_iterations", options.max_iterations,
                       "[1, " + std::to_string(kMaxLoadSharingIterations) + "]");
  }
}

[[noreturn]] void throw_cancelled(int iteration) {
  throw Cancelled("load sharing (eqs 20-22) stopped by its caller before iteration " +
                  std::to_string(iteration));
}

// Eq 22's fixed point q = eq22(x0 / q) where it falls on the hyperbolic branch (x >= 1:
// q = 1 - q / (2 x0), so q = 2 x0 / (2 x0 + 1)) or the linear one (0.4 <= x < 1: q^2 = 0.36 x0 +
// 0.14 q); on the root branch (x < 0.4, a quartic in q) the linear branch's root, a few per cent
// off, to start the iteration from.
double fixed_point_guess(double x0) {
  const double hyperbolic = 2.0 * x0 / (2.0 * x0 + 1.0);
  if (x0 >= hyperbolic) return hyperbolic;
  return 0.5 * (0.14 + std::sqrt(0.0196 + 1.44 * x0));
}

}  // namespace

LoadSharing solve_load_sharing(double mean_tooth_load_n, double stiffness_n_per_m,
                               double separation_m, const LoadSharingOptions& options) {
  validate(options);
  LoadSharing result;
  if (separation_m <= 0.0) {  // aligned: z_o = 0, every tooth shares equally
    result.ze_over_zo = std::numeric_limits<double>::infinity();
    return result;
  }
  // x(q) = z_e / z_o = P_t' / (q C z_o)   (eqs 10, 20, 21)
  const double x_at_unit_q = mean_tooth_load_n / (stiffness_n_per_m * separation_m);
  const auto residual = [x_at_unit_q](double q) { return load_sharing_ratio(x_at_unit_q / q) - q; };

  // residual(q) decreases in q; eq 22 never returns less than its x -> 0 limit, so the root
  // lies in [q_min, 1].
  double lo = load_sharing_ratio(0.0);
  double hi = 1.0;
  // The paper starts from the aligned coupling, q = 1, and took 2-9 steps of dependent divisions
  // and roots, a sixth of a load case. Started where the fixed point lies, a step or two.
  double q = std::clamp(fixed_point_guess(x_at_unit_q), lo, hi);
  double r = residual(q);
  double q_prev = q > 0.5 * (lo + hi) ? q - 1e-3 : q + 1e-3;  // a nearby second point: the first
  double r_prev = residual(q_prev);                           // secant step is nearly Newton's
  for (int i = 1; i <= options.max_iterations; ++i) {
    if (options.cancelled && options.cancelled()) throw_cancelled(i);
    if (std::abs(r) <= options.tolerance) {
      result.q = q;
      result.ze_over_zo = x_at_unit_q / q;
      result.iterations = i;
      return result;
    }
    (r > 0.0 ? lo : hi) = q;
    double next = q - r * (q - q_prev) / (r - r_prev);  // secant on residual
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    q_prev = q;
    r_prev = r;
    q = next;
    r = residual(q);
  }
  std::ostringstream message;
  message.precision(6);
  message << "load sharing (eqs 20-22) did not reach tolerance " << options.tolerance << " in "
          << options.max_iterations << " iterations; last q = " << q << ", residual = " << r;
  throw NotConverged(message.str());
}

}  // namespace gc
