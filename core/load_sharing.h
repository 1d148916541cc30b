// Load-sharing ratio q of Section 4.1: the iteration of eqs 20-22 that makes the assumed q equal
// the q that eq 22 returns for the resulting z_e / z_o.
#pragma once

#include <functional>

namespace gc {

/// Allowed tolerance on q [-]: the paper used 1e-3, the loosest allowed; below 1e-15 the
/// rounding of eq 22 near q = 1 (a few ulp) can make the tolerance unreachable.
inline constexpr double kMinLoadSharingTolerance = 1e-15;
inline constexpr double kMaxLoadSharingTolerance = 1e-3;
/// Most iterations a caller may ask for. The bracketed secant, started at the fixed point
/// (solve_load_sharing), converges in 1-6 iterations on the NREL couplings; the cap bounds the cost of a request that never converges
/// (10,000 iterations take well under a millisecond, docs/protocol.md).
inline constexpr int kMaxLoadSharingIterations = 10000;

struct LoadSharingOptions {
  double tolerance = 1e-9;  ///< stop when |q_eq22 - q_assumed| <= tolerance [-] (paper: 1e-3),
                            ///< in [kMinLoadSharingTolerance, kMaxLoadSharingTolerance]
  int max_iterations = 100; ///< in [1, kMaxLoadSharingIterations]; more is a NotConverged
                            ///< error, never a silent value
  /// Asked before every iteration; true stops the solve with Cancelled. Lets a caller (the
  /// service's per-calculation deadline, its shutdown) bound wall time while the core stays
  /// free of clocks and threads. Empty: never cancelled. Must be cheap and must not throw.
  std::function<bool()> cancelled;
};

struct LoadSharing {
  double q = 1.0;           ///< load-sharing ratio, mean over maximum tooth load [-]
  double ze_over_zo = 0.0;  ///< x = z_e / z_o at the solution (infinite when aligned)
  int iterations = 0;       ///< iterations used
};

/// Eq 22: q as a function of x = z_e / z_o, three branches that join continuously at x = 0.4
/// and x = 1. x must be >= 0; returns 1 for infinite x (no misalignment).
double load_sharing_ratio(double ze_over_zo);

/// Eqs 20-22 for mean tooth load P_t' [N], single-pair stiffness C [N/m] and maximum tooth
/// separation z_o [m]: P_i = P_t' / q (eq 20), z_e = P_i / C (eq 10), q <- eq 22. The map
/// q -> eq22(x(q)) is decreasing, so the fixed point is unique. The iteration starts there in
/// closed form on eq 22's linear and hyperbolic branches (one step: the check), and near it on the
/// root branch; each step keeps a bracket around it and falls back to bisection when a secant
/// step would leave it. z_o = 0 (aligned)
/// gives q = 1 at once. Throws InvalidInput naming "options.load_sharing.<member>" for options
/// out of range, NotConverged after options.max_iterations, Cancelled when
/// options.cancelled() returns true.
LoadSharing solve_load_sharing(double mean_tooth_load_n, double stiffness_n_per_m,
                               double separation_m, const LoadSharingOptions& options);

}  // namespace gc
