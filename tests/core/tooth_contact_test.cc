// Figure 8 of the paper: the upwind coupling at 1.5 MN·m and growing misalignment.
#include "core/tooth_contact.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include "core/coupling_geometry.h"
#include "core/induced_moments.h"
#include "core/model_error.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::deg;
using testing::nrel_upwind;

constexpr double kReferenceTorque = 1.5e6;  // [N·m], Section 6.3

ToothContact upwind_contact(double misalignment_deg) {
  static const CouplingGeometry coupling(nrel_upwind());
  return tooth_contact(coupling, {kReferenceTorque, deg(misalignment_deg), 0.0, 0.0});
}

TEST(ToothContactFigure8, AlignedEveryToothCarriesTheSameLoadAtTheFlankCentre) {
  const ToothContact c = upwind_contact(0.0);
  const double aligned = kReferenceTorque / (0.508 * std::cos(deg(20))) / 100;  // eqs 7, 20
  EXPECT_DOUBLE_EQ(c.load_sharing.q, 1.0);
  EXPECT_EQ(c.teeth_in_contact, 100);
  for (const ToothLoad& t : c.teeth) {
    EXPECT_NEAR(t.load_n, aligned, 1e-9);
    EXPECT_DOUBLE_EQ(t.contact_offset_m, 0.0);
    EXPECT_NEAR(t.zone_begin_m, -t.zone_end_m, 1e-15);  // centred on the flank
  }
  EXPECT_NEAR(c.sum_tooth_loads_n / c.total_normal_load_n, 1.0, 1e-12);
}

TEST(ToothContactFigure8, FewerTeethCarryMoreLoadAsMisalignmentGrows) {
  // q, loaded teeth and peak/aligned from an independent reading (model-notes.md, Python).
  struct Row { double deg, q, peak_ratio; int teeth; };
  const Row rows[] = {{0.1, 0.921, 1.09, 100}, {0.5, 0.367, 2.72, 58}, {0.74, 0.277, 3.60, 42}};
  const double aligned = upwind_contact(0.0).max_tooth_load_n;
  int previous_teeth = 101;
  double previous_peak = 0.0;
  for (const Row& row : rows) {
    const ToothContact c = upwind_contact(row.deg);
    EXPECT_NEAR(c.load_sharing.q, row.q, 2e-3) << row.deg;
    EXPECT_NEAR(c.max_tooth_load_n / aligned, row.peak_ratio, 0.02) << row.deg;
    EXPECT_NEAR(c.teeth_in_contact, row.teeth, 1) << row.deg;
    EXPECT_LE(c.teeth_in_contact, previous_teeth);
    EXPECT_GT(c.max_tooth_load_n, previous_peak);
    // eq 9 conserves the load exactly for x >= 1 and to within 2 % below (eq 22 is a fit).
    EXPECT_NEAR(c.sum_tooth_loads_n / c.total_normal_load_n, 1.0, 0.02) << row.deg;
    previous_teeth = c.teeth_in_contact;
    previous_peak = c.max_tooth_load_n;
  }
}

TEST(ToothContactFigure8, NearTheJamAnglePeakLoadIsAboutFourTimesTheAligned) {
  // Issue 2 / Section 6.1: 3.5-4.5 times the aligned load near the jam angle (0.7509 deg).
  const double aligned = upwind_contact(0.0).max_tooth_load_n;
  const ToothContact c = upwind_contact(0.75);
  EXPECT_GT(c.max_tooth_load_n / aligned, 3.5);
  EXPECT_LT(c.max_tooth_load_n / aligned, 4.5);
}

TEST(ToothContactFigure8, ContactMovesToFlankEdgesOnOppositeSides) {
  const ToothContact small = upwind_contact(0.1);
  const ToothContact large = upwind_contact(0.5);
  // Tooth 0 (at z'') and tooth N/2 (opposite) shift to opposite flank edges, eq 16.
  EXPECT_GT(large.teeth[0].contact_offset_m, 0.0);
  EXPECT_LT(large.teeth[50].contact_offset_m, 0.0);
  EXPECT_NEAR(large.teeth[0].contact_offset_m, -large.teeth[50].contact_offset_m, 1e-15);
  EXPECT_GT(large.teeth[0].contact_offset_m, 4.0 * small.teeth[0].contact_offset_m);
  EXPECT_NEAR(large.max_contact_offset_m, 2.5851656 * std::sin(deg(0.5)), 1e-7);  // eq 15
}

TEST(ToothContactFigure8, PaperAngleBeyondDerivedJamAngleIsRejectedNamingTheField) {
  // 0.8 deg lies beyond the 0.7509 deg jam angle of the derived crown radius.
  try {
    upwind_contact(0.8);
    FAIL() << "0.8 deg must be rejected";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "operating_point.misalignment_rad");
    EXPECT_NE(std::string(e.what()).find("jam angle"), std::string::npos);
  }
}

TEST(ToothContactFigure8, PaperAngleRunsWithTheTable3CrownRadius) {
  // With R_F = 1.6406 m (jam 0.9 deg, Table 3) the paper's 0.8 deg panel can be computed.
  CouplingDefinition d = nrel_upwind();
  d.crown_radius_m = 1.6406;
  const CouplingGeometry coupling(d);
  const double aligned = tooth_contact(coupling, {kReferenceTorque, 0.0, 0.0, 0.0}).max_tooth_load_n;
  const ToothContact c = tooth_contact(coupling, {kReferenceTorque, deg(0.8), 0.0, 0.0});
  // Independent Python reading: q = 0.3073, 48 loaded teeth, peak 3.25 x aligned.
  EXPECT_NEAR(c.load_sharing.q, 0.3073, 1e-3);
  EXPECT_NEAR(c.teeth_in_contact, 48, 1);
  EXPECT_NEAR(c.max_tooth_load_n / aligned, 3.25, 0.02);
}

TEST(ToothContact, ContactZoneFollowsEqs16To19) {
  const ToothContact c = upwind_contact(0.5);
  const double crown = CouplingGeometry(nrel_upwind()).crown_radius_m();
  const double stiffness = CouplingGeometry(nrel_upwind()).mesh_stiffness_n_per_m();
  const ToothLoad& t = c.teeth[3];
  EXPECT_NEAR(t.deformation_m, t.load_n / stiffness, 1e-18);                    // eq 17
  EXPECT_NEAR(t.contact_length_m,
              2 * std::sqrt(crown * crown - std::pow(crown - t.deformation_m, 2)), 1e-12);  // 18
  EXPECT_NEAR(t.contact_offset_m, crown * std::sin(deg(0.5)) * std::cos(t.angle_rad), 1e-9);  // 16
  EXPECT_NEAR(t.zone_begin_m, t.contact_offset_m - t.contact_length_m / 2, 1e-15);  // eq 19
  EXPECT_NEAR(t.zone_end_m, t.contact_offset_m + t.contact_length_m / 2, 1e-15);
}

TEST(ToothContact, DownwindBecomesEdgeLoadedNearItsJamAngle) {
  // Section 7: "in the extreme, the teeth are edge-loaded". At 1.5 MN·m the downwind coupling's
  // zones reach the facewidth edge from about 88 % of its 1.7217 deg jam angle (1.515 deg);
  // the upwind coupling's never do (largest |F_d| + F_c/2 = 53.6 mm of 63.5 mm).
  const CouplingGeometry downwind(testing::nrel_downwind());
  EXPECT_FALSE(tooth_contact(downwind, {kReferenceTorque, deg(1.50), 0.0, 0.0}).edge_loaded);
  const ToothContact edge = tooth_contact(downwind, {kReferenceTorque, deg(1.53), 0.0, 0.0});
  EXPECT_TRUE(edge.edge_loaded);
  for (const ToothLoad& t : edge.teeth) {
    EXPECT_GE(t.zone_begin_m, -0.0635);
    EXPECT_LE(t.zone_end_m, 0.0635);
  }
  EXPECT_FALSE(upwind_contact(0.75).edge_loaded);
}

TEST(ToothContact, UnloadedTeethHaveNoContactZone) {
  const ToothContact c = upwind_contact(0.5);
  const ToothLoad& side = c.teeth[25];  // 90 deg from z'': the largest separation
  EXPECT_EQ(side.load_n, 0.0);
  EXPECT_FALSE(side.in_contact());
  EXPECT_EQ(side.contact_length_m, 0.0);
}

// Found by wire_request_fuzzer on the array form of eq 9: a torque of 1.9e-317 N·m (z_e
// underflows to 0) with a misalignment of 2.6e-251 rad (z_o is 0) makes z_o / z_e = 0 / 0; eq 9's
// clip at zero must give no load there, as it does for any other share below zero, not NaN.
TEST(ToothContact, AVanishingTorqueAndMisalignmentLoadNoToothWithNaN) {
  const CouplingGeometry coupling(nrel_upwind());
  ContactOptions options;
  options.min_load_fraction = 0.0;
  const ToothContact c = tooth_contact(coupling, {1.942745e-317, 2.6353696886160664e-251, 0.3, 0.0}, options);
  for (const ToothLoad& tooth : c.teeth) {
    EXPECT_EQ(tooth.load_n, 0.0);
    EXPECT_EQ(tooth.deformation_m, 0.0);
  }
  EXPECT_EQ(c.teeth_in_contact, 0);
}

TEST(ToothContact, MaxLoadSitsOnTheZDoublePrimeAxis) {
  // Eq 9 peaks where sin(theta_j) = 0: the tooth nearest z'' or its opposite (alpha shifts
  // the pattern by up to a quarter pitch, so either side may hold the single largest load).
  const ToothContact c = upwind_contact(0.5);
  const double angle = c.teeth[c.max_load_tooth].angle_rad;
  EXPECT_LT(std::abs(std::sin(angle)), std::sin(2 * M_PI / 100));
  for (const ToothLoad& t : c.teeth) EXPECT_LE(std::abs(std::sin(angle)), std::abs(std::sin(t.angle_rad)));
  EXPECT_NEAR(c.z_axis_angle_rad, deg(20), 1e-15);                  // phi + beta, beta = 0
}

TEST(ToothContact, SliceLoadsFollowEq14) {
  const ToothContact c = upwind_contact(0.5);
  const Eigen::MatrixXd slices = c.slice_loads();
  ASSERT_EQ(slices.rows(), 100);
  ASSERT_EQ(slices.cols(), 21);  // N_s = 20: l = -10 .. 10
  EXPECT_DOUBLE_EQ(slices(0, 10), c.teeth[0].load_n);  // l = 0, cos 0
  EXPECT_NEAR(slices(0, 0), 0.0, 1e-9 * c.teeth[0].load_n);  // l = -N_s/2, cos(-pi/2)
  EXPECT_NEAR(slices(0, 5), c.teeth[0].load_n * std::cos(M_PI * -5 / 20), 1e-9);
  EXPECT_NEAR(c.slice_position_m(0, 10), c.teeth[0].zone_end_m, 1e-12);
  EXPECT_NEAR(c.slice_position_m(0, -10), c.teeth[0].zone_begin_m, 1e-12);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_contact(const ToothContact& a, const ToothContact& b, const std::string& at) {
  for (const auto& [name, x, y] : {
           std::tuple{"q", a.load_sharing.q, b.load_sharing.q},
           std::tuple{"x", a.load_sharing.ze_over_zo, b.load_sharing.ze_over_zo},
           std::tuple{"P_t", a.total_normal_load_n, b.total_normal_load_n},
           std::tuple{"P_t'", a.mean_tooth_load_n, b.mean_tooth_load_n},
           std::tuple{"P_i", a.peak_tooth_load_n, b.peak_tooth_load_n},
           std::tuple{"z_e", a.elastic_deformation_m, b.elastic_deformation_m},
           std::tuple{"z_o", a.max_separation_m, b.max_separation_m},
           std::tuple{"alpha", a.offset_alpha_rad, b.offset_alpha_rad},
           std::tuple{"F_i", a.max_contact_offset_m, b.max_contact_offset_m},
           std::tuple{"z''", a.z_axis_angle_rad, b.z_axis_angle_rad},
           std::tuple{"max P_d", a.max_tooth_load_n, b.max_tooth_load_n},
           std::tuple{"sum P_d", a.sum_tooth_loads_n, b.sum_tooth_loads_n},
           std::tuple{"contact stress", a.max_stress.contact_stress_pa, b.max_stress.contact_stress_pa},
           std::tuple{"half width", a.max_stress.contact_half_width_m, b.max_stress.contact_half_width_m},
           std::tuple{"bending stress", a.max_stress.bending_stress_pa, b.max_stress.bending_stress_pa},
           std::tuple{"S_H", a.max_stress.contact_safety_factor, b.max_stress.contact_safety_factor},
           std::tuple{"S_F", a.max_stress.bending_safety_factor, b.max_stress.bending_safety_factor}}) {
    EXPECT_TRUE(same_bits(x, y)) << name << " " << x << " " << y << at;
  }
  EXPECT_EQ(a.load_sharing.iterations, b.load_sharing.iterations) << at;
  EXPECT_EQ(a.teeth_in_contact, b.teeth_in_contact) << at;
  EXPECT_EQ(a.max_load_tooth, b.max_load_tooth) << at;
  EXPECT_EQ(a.edge_loaded, b.edge_loaded) << at;
  EXPECT_EQ(a.slices, b.slices) << at;
  EXPECT_EQ(a.continuous_quarter_sums, b.continuous_quarter_sums) << at;
}

// tooth_contact_without_teeth() reports the counts, the largest load, the sum, edge_loaded and
// the stress from closed forms without the table; list_teeth() then derives the table. Both must
// be tooth_contact()'s to the bit: over both couplings, light torque to heavy, aligned to 99.9 %
// of the jam angle, a spacing error and the continuous variant, and finely across the downwind
// coupling's first edge-loaded angle (about 88 % of its jam angle at 1.5 MN·m), where
// edge_loaded leaves its shortcut and visits the teeth.
TEST(ToothContact, WithoutTeethThenListTeethIsBitForBitTheFullContact) {
  ContactOptions permissive;
  permissive.min_load_fraction = 0.0;
  ContactOptions spaced;
  spaced.spacing_error_m = 2e-5;
  spaced.continuous_quarter_sums = true;
  std::vector<double> fractions = {0.0, 0.01, 0.2, 0.5, 0.8, 0.95, 0.999};
  for (double f = 0.86; f < 0.90; f += 0.0005) fractions.push_back(f);
  ToothContact reused;  // its storage kept across points, as a batch keeps it
  int edge_loaded = 0;
  for (const CouplingGeometry& coupling : {CouplingGeometry(nrel_upwind()), CouplingGeometry(testing::nrel_downwind())}) {
    for (const ContactOptions& options : {ContactOptions{}, permissive, spaced}) {
      for (double torque : {1e3, 2e5, 1.5e6, 5e6}) {
        for (double fraction : fractions) {
          const OperatingPoint point{torque, fraction * coupling.jam_angle().angle_rad, 0.7, 0.1};
          const std::string at = " at " + coupling.name() + ", " + std::to_string(torque) + " N·m, " +
                                 std::to_string(fraction) + " of the jam angle";
          ToothContact full;
          try {
            full = tooth_contact(coupling, point, options);
          } catch (const InvalidInput&) {  // light torque near the jam angle: the same refusal
            EXPECT_THROW(tooth_contact_without_teeth(coupling, point, options, reused), InvalidInput) << at;
            continue;
          }
          tooth_contact_without_teeth(coupling, point, options, reused);
          EXPECT_TRUE(reused.teeth.empty()) << at;
          expect_same_contact(full, reused, at);
          edge_loaded += reused.edge_loaded;
          const InducedMoments from_full = induced_moments(coupling, point, full);
          const InducedMoments from_members = induced_moments(coupling, point, reused);  // no table
          EXPECT_TRUE(same_bits(from_full.moment_y_nm, from_members.moment_y_nm) &&
                      same_bits(from_full.moment_z_nm, from_members.moment_z_nm)) << at;
          list_teeth(coupling, reused);
          ASSERT_EQ(reused.teeth.size(), full.teeth.size()) << at;
          for (std::size_t j = 0; j < full.teeth.size(); ++j) {
            const ToothLoad& a = full.teeth[j];
            const ToothLoad& b = reused.teeth[j];
            EXPECT_TRUE(same_bits(a.angle_rad, b.angle_rad) && same_bits(a.load_n, b.load_n) &&
                        same_bits(a.contact_offset_m, b.contact_offset_m) &&
                        same_bits(a.deformation_m, b.deformation_m) &&
                        same_bits(a.contact_length_m, b.contact_length_m) &&
                        same_bits(a.zone_begin_m, b.zone_begin_m) && same_bits(a.zone_end_m, b.zone_end_m))
                << "tooth " << j << at;
          }
        }
      }
    }
  }
  EXPECT_GT(edge_loaded, 20);  // the sweep reached the teeth-visiting branch
}

TEST(ToothContact, DirectionRotatesOnlyTheFrame) {
  static const CouplingGeometry coupling(nrel_upwind());
  const ToothContact a = tooth_contact(coupling, {kReferenceTorque, deg(0.4), 0.0, 0.0});
  const ToothContact b = tooth_contact(coupling, {kReferenceTorque, deg(0.4), deg(70), 0.0});
  EXPECT_EQ(a.max_tooth_load_n, b.max_tooth_load_n);
  EXPECT_NEAR(b.z_axis_angle_rad - a.z_axis_angle_rad, deg(70), 1e-15);
}

}  // namespace
}  // namespace gc
