// A control program built against the installed package with gearcoupling::physics alone: the
// jam angle of the NREL upwind coupling (Table 1, as tests/core/nrel_couplings.h writes it, which
// physics_alone_test.sh copies beside this file), no file read, no diagnosis linked.
//   physics_consumer     (exit 0 when the jam angle is the paper's)
#include <cmath>
#include <cstdio>
#include <exception>

#include "nrel_couplings.h"

int main() {
  try {
    const double jam_deg = gc::testing::to_deg(gc::testing::upwind_geometry().jam_angle().angle_rad);
    std::printf("jam angle nrel_upwind: %.4f deg\n", jam_deg);
    // 0.7509 deg: eq 23 with the derived crown radius (tests/core/jam_angle_test.cc).
    return std::abs(jam_deg - 0.7509) < 5e-4 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "physics_consumer: %s\n", e.what());
    return 1;
  }
}
