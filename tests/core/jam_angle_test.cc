#include "core/jam_angle.h"

#include <gtest/gtest.h>

#include "core/coupling_geometry.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::deg;
using testing::nrel_downwind;
using testing::nrel_upwind;
using testing::to_deg;

JamGeometry jam_geometry(const CouplingGeometry& g) {
  return {g.crown_radius_m(), g.hub_tooth_thickness_m(), g.sleeve_space_width_m(),
          g.facewidth_m(), g.pressure_angle_rad(), g.backlash_m()};
}

// Small-angle form of eq 23 (model-notes.md): R_F xi^2 + F sin^2(phi) xi = b.
double small_angle_jam_rad(const CouplingGeometry& g) {
  const double a = g.crown_radius_m();
  const double s = std::sin(g.pressure_angle_rad());
  const double b = g.facewidth_m() * s * s;
  return (-b + std::sqrt(b * b + 4 * a * g.backlash_m())) / (2 * a);
}

TEST(JamAngle, UpwindWithDerivedCrownRadiusIsEq23Governed) {
  // Independent reading (model-notes.md): about 0.75 deg; Table 3: 0.9 deg (see docs/model.md).
  const JamAngle jam = CouplingGeometry(nrel_upwind()).jam_angle();
  EXPECT_EQ(jam.governing, JamCriterion::kBothFlanks);
  EXPECT_NEAR(to_deg(jam.angle_rad), 0.7509, 5e-4);
  EXPECT_NEAR(to_deg(jam.facewidth_rad), 1.408, 1e-3);  // asin(F / 2 R_F), eq 30
  EXPECT_NEAR(to_deg(jam.radial_rad), 0.844, 1e-3);     // asin(b / F sin phi), eq 34
}

TEST(JamAngle, DownwindWithDerivedCrownRadiusIsEq23Governed) {
  // Independent reading: about 1.72 deg; Table 3: 1.8 deg.
  const JamAngle jam = CouplingGeometry(nrel_downwind()).jam_angle();
  EXPECT_EQ(jam.governing, JamCriterion::kBothFlanks);
  EXPECT_NEAR(to_deg(jam.angle_rad), 1.7217, 5e-4);
  EXPECT_NEAR(to_deg(jam.facewidth_rad), 2.165, 1e-3);
  EXPECT_NEAR(to_deg(jam.radial_rad), 2.599, 1e-3);
}

TEST(JamAngle, FullEq23AgreesWithItsSmallAngleForm) {
  for (const auto& d : {nrel_upwind(), nrel_downwind()}) {
    const CouplingGeometry g(d);
    EXPECT_NEAR(g.jam_angle().angle_rad / small_angle_jam_rad(g), 1.0, 2e-3) << d.name;
  }
}

TEST(JamAngle, RootMakesEq23ResidualVanish) {
  const CouplingGeometry g(nrel_upwind());
  const JamAngle jam = g.jam_angle();
  ASSERT_TRUE(jam.both_flanks_rad.has_value());
  EXPECT_NEAR(both_flanks_residual_m(jam_geometry(g), *jam.both_flanks_rad), 0.0, 1e-15);
  EXPECT_NEAR(both_flanks_residual_m(jam_geometry(g), 0.0), -g.backlash_m(), 1e-15);
}

TEST(JamAngle, CrownRadiiThatReproduceTable3) {
  // Eq 23 alone needs R_F about 1640 mm upwind and 1520 mm downwind (model-notes.md).
  const double upwind = crown_radius_for_both_flanks_jam(jam_geometry(CouplingGeometry(nrel_upwind())), deg(0.9));
  const double downwind =
      crown_radius_for_both_flanks_jam(jam_geometry(CouplingGeometry(nrel_downwind())), deg(1.8));
  EXPECT_NEAR(upwind, 1.6406, 5e-4);
  EXPECT_NEAR(downwind, 1.5164, 5e-4);
  CouplingDefinition d = nrel_downwind();
  d.crown_radius_m = downwind;
  const JamAngle jam = CouplingGeometry(d).jam_angle();
  EXPECT_NEAR(to_deg(jam.angle_rad), 1.8, 1e-9);
  EXPECT_EQ(jam.governing, JamCriterion::kBothFlanks);
}

TEST(JamAngle, Table3UpwindLiesBeyondTheRadialLimitOfEq34) {
  // Whatever R_F, eq 35 cannot exceed eq 34's asin(b / F sin phi) = 0.8442 deg for the upwind
  // coupling, so Table 3's 0.9 deg is out of reach of eq 35: with R_F = 1640.6 mm eq 23 gives
  // 0.9 deg but the radial criterion governs.
  CouplingDefinition d = nrel_upwind();
  d.crown_radius_m = 1.6406;
  const JamAngle jam = CouplingGeometry(d).jam_angle();
  ASSERT_TRUE(jam.both_flanks_rad.has_value());
  EXPECT_NEAR(to_deg(*jam.both_flanks_rad), 0.9, 2e-4);
  EXPECT_EQ(jam.governing, JamCriterion::kRadial);
  EXPECT_NEAR(to_deg(jam.angle_rad), 0.8442, 1e-4);
}

TEST(JamAngle, RadialCriterionGovernsWhenBacklashIsLargeAgainstFacewidth) {
  // A wide face: eq 23 is dominated by F sin^2(phi) xi = b, whose root b / (F sin^2 phi) lies
  // beyond eq 34's asin(b / F sin phi).
  CouplingDefinition d = nrel_upwind();
  d.facewidth_m = 0.5;
  d.crown_radius_m = 5.0;
  const JamAngle jam = CouplingGeometry(d).jam_angle();
  EXPECT_EQ(jam.governing, JamCriterion::kRadial);
  EXPECT_NEAR(jam.angle_rad, std::asin(0.00064 / (0.5 * std::sin(deg(20)))), 1e-12);
}

TEST(JamAngle, FacewidthCriterionGovernsForAFlatCrown) {
  // A flat crown with generous backlash: F / (2 R_F) < sqrt(b / R_F), so the contact leaves the
  // face (eq 30) before eq 23 closes the space, and eq 23 has no root below that limit.
  CouplingDefinition d = nrel_downwind();
  d.crown_radius_m = 5.0;
  d.backlash_m = 0.002;
  const JamAngle jam = CouplingGeometry(d).jam_angle();
  EXPECT_EQ(jam.governing, JamCriterion::kFacewidth);
  EXPECT_FALSE(jam.both_flanks_rad.has_value());
  EXPECT_NEAR(jam.angle_rad, std::asin(0.127 / 10.0), 1e-12);
}

}  // namespace
}  // namespace gc
