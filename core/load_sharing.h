// Load-sharing ratio q of Section 4.1: the iteration of eqs 20-22 that makes the assumed q equal
// the q that eq 22 returns for the resulting z_e / z_o.
#pragma once

namespace gc {

struct LoadSharingOptions {
  double tolerance = 1e-9;  ///< stop when |q_eq22 - q_assumed| <= tolerance [-] (paper: 1e-3)
  int max_iterations = 100; ///< more is a NotConverged error, never a silent value
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
/// q -> eq22(x(q)) is decreasing, so the fixed point is unique; each step keeps a bracket
/// around it and falls back to bisection when a secant step would leave it. z_o = 0 (aligned)
/// gives q = 1 at once. Throws NotConverged after options.max_iterations.
LoadSharing solve_load_sharing(double mean_tooth_load_n, double stiffness_n_per_m,
                               double separation_m, const LoadSharingOptions& options);

}  // namespace gc
