#include "core/restoring_torque.h"

#include <gtest/gtest.h>

#include "core/coupling_geometry.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::nrel_downwind;
using testing::nrel_upwind;

TEST(RestoringTorque, ReproducesTable4ModelValueForBothCouplings) {
  // Table 4: 1.36 MN·m for both. W = W_c + 0.5 w_sh L_s = 24 kN + 29.54 kN = 53.54 kN;
  // T_m = N R W / N_c,s = 100 * 0.508 * 53540 / 2 = 1.3599 MN·m (docs/model.md, eq 52 as read).
  for (const auto& d : {nrel_upwind(), nrel_downwind()}) {
    const RestoringTorque r = restoring_torque(CouplingGeometry(d));
    EXPECT_EQ(r.contact, RootContact::kSleeveSides) << d.name;
    EXPECT_EQ(r.teeth_in_contact, 2) << d.name;
    EXPECT_NEAR(r.supported_weight_n, 53540.0, 1e-9);
    EXPECT_NEAR(r.torque_nm / 1e6, 1.36, 0.005) << d.name;
  }
}

TEST(RestoringTorque, AccessibleClearanceEq49AgainstDesignClearance) {
  const RestoringTorque up = restoring_torque(CouplingGeometry(nrel_upwind()));
  EXPECT_NEAR(up.accessible_clearance_m, 0.00064 / (2 * std::sin(20 * M_PI / 180)), 1e-15);
  EXPECT_NEAR(up.design_clearance_m, 0.5 * ((2 * 1.016 - 0.98877) - 1.03632), 1e-15);
  EXPECT_LT(up.accessible_clearance_m, up.design_clearance_m);
}

TEST(RestoringTorque, HeavierHubLoadsMoreSideTeethEq53) {
  // The sag W / (2 N C) must exceed b (1 - cos(2 pi l / N)) for side tooth l to join.
  CouplingDefinition d = nrel_upwind();
  d.coupling_weight_n = 2.0e6;  // sag 6.9 um > 0.64 mm * (1 - cos 3.6 deg) = 1.26 um
  const RestoringTorque r = restoring_torque(CouplingGeometry(d));
  EXPECT_GT(r.teeth_in_contact, 2);
  int expected = 2;
  for (int l = 1; l <= 50; ++l) {
    if (0.00064 * (1 - std::cos(2 * M_PI * l / 100)) < r.sag_m) expected += 2;
  }
  EXPECT_EQ(r.teeth_in_contact, expected);
  EXPECT_NEAR(r.torque_nm, 100 * 0.508 * r.supported_weight_n / expected, 1e-6);
}

TEST(RestoringTorque, ShallowSleeveRootRestsTheHubOnTheBottomEqs50And51) {
  CouplingDefinition d = nrel_upwind();
  d.sleeve_root_diameter_m = 1.03632 + 2 * 0.0005;  // Delta_r = 0.5 mm < Delta_c = 0.936 mm
  const RestoringTorque r = restoring_torque(CouplingGeometry(d));
  EXPECT_EQ(r.contact, RootContact::kSleeveBottom);
  EXPECT_NEAR(r.design_clearance_m, 0.0005, 1e-12);
  // Eq 51 for k = N/4 .. 3N/4: cos(2 pi k / N) <= 0, so every tooth of the lower half joins
  // while the sag is below the backlash: N_c,b = 2 + 51.
  EXPECT_EQ(r.teeth_in_contact, 53);
  EXPECT_NEAR(r.torque_nm, 100 * 0.508 * 53540.0 / (53 * std::cos(20 * M_PI / 180)), 1e-6);
}

TEST(RestoringTorque, NoWeightNeedsNoTorque) {
  CouplingDefinition d = nrel_upwind();
  d.coupling_weight_n = 0.0;
  d.shaft_weight_per_length_n_per_m = 0.0;
  EXPECT_EQ(restoring_torque(CouplingGeometry(d)).torque_nm, 0.0);
}

}  // namespace
}  // namespace gc
