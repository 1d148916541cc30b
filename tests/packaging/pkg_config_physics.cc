// Compiled by tests/packaging/pkg_config_test.sh with only
// `pkg-config --cflags --libs gearcoupling-physics` (and again with gearcoupling-core, which
// brings it) against the installed package.
#include <cmath>
#include <cstdio>

#include "core/crown_radius.h"
#include "core/tooth_contact.h"  // includes Eigen: pkg-config's Requires brings its -I

int main() {
  // nrel_upwind's lead modification: R_F = ((F/2)^2 + d^2) / (2 d) = 2.585 m
  // (data/couplings/nrel_upwind.textproto).
  const double crown_radius_m = gc::crown_radius_from_lead_modification(0.127, 0.00078);
  std::printf("R_F = %.4f m\n", crown_radius_m);
  return std::abs(crown_radius_m - 2.5852) < 1e-4 ? 0 : 1;
}
