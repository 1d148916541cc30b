#include "core/stress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/coupling_geometry.h"
#include "core/tooth_contact.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::deg;
using testing::nrel_upwind;

TEST(ToothStress, HertzLineContactOfTheCrownOnTheFlank) {
  // Hand calculation: P = 31.42 kN, E* = 206e9 / (2 (1 - 0.09)) = 113.19 GPa,
  // L = 20.32 mm / cos 20 = 21.62 mm, R' = R_F = 2.5852 m:
  // p = sqrt(P E* / (pi L R')) = 142.3 MPa, a = sqrt(4 P R' / (pi L E*)) = 6.50 mm.
  const CouplingGeometry g(nrel_upwind());
  const double load = 1.5e6 / (0.508 * std::cos(deg(20))) / 100;
  const ToothStress s = tooth_stress(g, load, 0.021);
  EXPECT_NEAR(s.contact_stress_pa / 1e6, 142.3, 0.3);
  EXPECT_NEAR(s.contact_half_width_m * 1e3, 6.50, 0.02);
  EXPECT_NEAR(s.contact_safety_factor, 1.1e9 / s.contact_stress_pa, 1e-12);
}

TEST(ToothStress, BendingOnTheLoadedFaceLengthWithTheFormFactor) {
  // sigma = P cos(phi) / (F_e m Y), F_e = F_c + 2 h_t = 21 + 2 * 23.775 = 68.55 mm:
  // 31.42 kN * 0.9397 / (0.06855 * 0.01016 * 0.45) = 94.2 MPa.
  const CouplingGeometry g(nrel_upwind());
  const double load = 1.5e6 / (0.508 * std::cos(deg(20))) / 100;
  const ToothStress s = tooth_stress(g, load, 0.021);
  EXPECT_NEAR(s.bending_stress_pa / 1e6, 94.2, 0.1);
  EXPECT_NEAR(s.bending_safety_factor, 3.1e8 / s.bending_stress_pa, 1e-12);
  // A spread wider than the face is capped at F.
  const ToothStress capped = tooth_stress(g, load, 0.1);
  EXPECT_NEAR(capped.bending_stress_pa, load * std::cos(deg(20)) / (0.127 * 0.01016 * 0.45), 1e-6);
}

TEST(ToothStress, UnloadedToothHasNoStressAndFiniteSafety) {
  const ToothStress s = tooth_stress(CouplingGeometry(nrel_upwind()), 0.0, 0.0);
  EXPECT_EQ(s.contact_stress_pa, 0.0);
  EXPECT_EQ(s.bending_stress_pa, 0.0);
  EXPECT_EQ(s.contact_safety_factor, std::numeric_limits<double>::max());
}

TEST(ToothStress, MisalignmentRaisesTheGoverningStress) {
  const CouplingGeometry g(nrel_upwind());
  const ToothContact aligned = tooth_contact(g, {1.5e6, 0.0, 0.0, 0.0});
  const ToothContact misaligned = tooth_contact(g, {1.5e6, deg(0.6), 0.0, 0.0});
  EXPECT_GT(misaligned.max_stress.contact_stress_pa, 1.5 * aligned.max_stress.contact_stress_pa);
  EXPECT_LT(misaligned.max_stress.contact_safety_factor, aligned.max_stress.contact_safety_factor);
  // Hertz pressure grows as sqrt(P): ratio of pressures = sqrt(ratio of loads).
  EXPECT_NEAR(misaligned.max_stress.contact_stress_pa / aligned.max_stress.contact_stress_pa,
              std::sqrt(misaligned.max_tooth_load_n / aligned.max_tooth_load_n), 1e-12);
}

// Found by fuzz/wire_request_fuzzer: a torque of 4.7e-306 N·m (inside (0, 1e12]) gave a
// bending stress so small that allowable / stress overflowed to an infinite safety factor.
TEST(ToothStress, SafetyOfAVanishingStressIsTheLargestDoubleNotInfinity) {
  const CouplingGeometry g(nrel_upwind());
  ContactOptions options;
  options.min_load_fraction = 0.0;  // as the fuzzer sent it: the loads reported as they are
  const ToothContact c = tooth_contact(
      g, {4.720285590148793e-306, 2.635369688616265e-251, 0.3000489214830563, 3.4332275458837105e-05},
      options);
  EXPECT_GT(c.max_stress.bending_stress_pa, 0.0);
  EXPECT_EQ(c.max_stress.bending_safety_factor, std::numeric_limits<double>::max());
  EXPECT_EQ(c.max_stress.contact_safety_factor,
            g.definition().allowables.contact_stress_pa / c.max_stress.contact_stress_pa);
  EXPECT_TRUE(std::isfinite(c.max_stress.contact_safety_factor));
}

}  // namespace
}  // namespace gc
