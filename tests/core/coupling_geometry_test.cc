#include "core/coupling_geometry.h"

#include <gtest/gtest.h>

#include "core/crown_radius.h"
#include "core/tooth_stiffness.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::nrel_downwind;
using testing::nrel_upwind;

TEST(CouplingGeometry, PitchRadiusIsHalfThePitchDiameterEq8) {
  const CouplingGeometry g(nrel_upwind());
  EXPECT_DOUBLE_EQ(g.pitch_radius_m(), 0.508);
  EXPECT_NEAR(g.diametral_pitch_per_m(), 100 / 1.016, 1e-12);
}

TEST(CouplingGeometry, SleeveToothFollowsFromBacklashEq27) {
  // S_c2 = t_c1 + b = 16.19 mm; t_c2 = pi m - S_c2 = 31.918 - 16.19 = 15.728 mm (hand).
  const CouplingGeometry g(nrel_upwind());
  EXPECT_NEAR(g.sleeve_space_width_m(), 0.01619, 1e-12);
  EXPECT_NEAR(g.sleeve_tooth_thickness_m(), M_PI * 0.01016 - 0.01619, 1e-12);
}

TEST(CrownRadius, FromLeadModificationMatchesNotes) {
  // model-notes.md: 2585 mm upwind, 1681 mm downwind.
  // Hand: (63.5^2 + 0.78^2) / 1.56 = 2585.1656 mm; (63.5^2 + 1.2^2) / 2.4 = 1680.7042 mm.
  EXPECT_NEAR(crown_radius_from_lead_modification(0.127, 0.00078), 2.5851656, 1e-7);
  EXPECT_NEAR(crown_radius_from_lead_modification(0.127, 0.0012), 1.6807042, 1e-7);
  EXPECT_NEAR(CouplingGeometry(nrel_upwind()).crown_radius_m(), 2.5851656, 1e-7);
  EXPECT_TRUE(CouplingGeometry(nrel_upwind()).crown_radius_derived());
}

TEST(CrownRadius, GivenRadiusOverridesLeadModification) {
  CouplingDefinition d = nrel_upwind();
  d.crown_radius_m = 1.6406;
  const CouplingGeometry g(d);
  EXPECT_DOUBLE_EQ(g.crown_radius_m(), 1.6406);
  EXPECT_FALSE(g.crown_radius_derived());
}

TEST(ToothStiffness, SinglePairStiffnessEqs5And6) {
  // Z = 0.45 / (0.76 + 7.25 * 0.45) = 0.111871; C = F E Z / 2 = 1.4635e9 N/m (model-notes.md).
  EXPECT_NEAR(elasticity_factor(0.45), 0.45 / 4.0225, 1e-15);
  const double c = single_pair_stiffness(0.127, 2.06e11, 0.45, 0.45);
  EXPECT_NEAR(c, 0.127 * 2.06e11 * (0.45 / 4.0225) / 2.0, 1.0);
  EXPECT_NEAR(c / 1e9, 1.4635, 5e-4);
  EXPECT_DOUBLE_EQ(CouplingGeometry(nrel_upwind()).mesh_stiffness_n_per_m(), c);
}

TEST(ToothStiffness, FormFactorRangeMovesStiffnessAboutFivePercent) {
  const double low = single_pair_stiffness(0.127, 2.06e11, 0.35, 0.35);
  const double high = single_pair_stiffness(0.127, 2.06e11, 0.6, 0.6);
  EXPECT_NEAR(high / low - 1.0, 0.10, 0.03);  // +-5 % around Y = 0.45
}

TEST(CouplingGeometry, RootCrownRadiusEq12) {
  CouplingDefinition d = nrel_upwind();
  d.design_misalignment_rad = testing::deg(1.0);
  const CouplingGeometry g(d);
  EXPECT_NEAR(g.root_crown_radius_m(),
              g.crown_radius_m() * std::cos(testing::deg(1.0)) * std::sin(testing::deg(20.0)),
              1e-15);
}

TEST(CouplingGeometry, SleeveRootMirrorsHubDedendumWhenNotGiven) {
  const CouplingGeometry g(nrel_upwind());
  EXPECT_NEAR(g.sleeve_root_diameter_m(), 2 * 1.016 - 0.98877, 1e-15);
  EXPECT_NEAR(g.working_depth_m(), 1.03632 - 1.016, 1e-15);
}

}  // namespace
}  // namespace gc
