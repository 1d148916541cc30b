// Every entry point rejects non-physical input with an InvalidInput naming the field.
#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include "core/coupling_geometry.h"
#include "core/induced_moments.h"
#include "core/model_error.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::deg;
using testing::nrel_upwind;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string field_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(e.field()), std::string::npos) << "message names field";
    return e.field();
  }
  return "(accepted)";
}

std::string coupling_field(const std::function<void(CouplingDefinition&)>& spoil) {
  CouplingDefinition d = nrel_upwind();
  spoil(d);
  return field_of([&] { CouplingGeometry{d}; });
}

TEST(InputValidation, CouplingDefinitionErrorsNameTheField) {
  EXPECT_EQ(coupling_field([](auto& d) { d.teeth = 0; }), "coupling.teeth");
  EXPECT_EQ(coupling_field([](auto& d) { d.teeth = -4; }), "coupling.teeth");
  EXPECT_EQ(coupling_field([](auto& d) { d.facewidth_m = 0.0; }), "coupling.facewidth_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.facewidth_m = kNaN; }), "coupling.facewidth_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.backlash_m = -1e-4; }), "coupling.backlash_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.tooth_thickness_m = 0.032; }),
            "coupling.tooth_thickness_m");  // thicker than the circular pitch
  EXPECT_EQ(coupling_field([](auto& d) { d.module_m = kInf; }), "coupling.module_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.pitch_diameter_m = 1.2; }),
            "coupling.pitch_diameter_m");  // not N * module
  EXPECT_EQ(coupling_field([](auto& d) { d.root_diameter_m = 1.02; }), "coupling.root_diameter_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.youngs_modulus_pa = -1.0; }),
            "coupling.youngs_modulus_pa");
  EXPECT_EQ(coupling_field([](auto& d) { d.crown_radius_m = 0.05; }), "coupling.crown_radius_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.lead_modification_m = 0.0; }),
            "coupling.lead_modification_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.form_factor_hub = 3.0; }), "coupling.form_factor_hub");
  EXPECT_EQ(coupling_field([](auto& d) { d.coupling_weight_n = -5.0; }),
            "coupling.coupling_weight_n");
  EXPECT_EQ(coupling_field([](auto& d) { d.allowables.contact_stress_pa = 0.0; }),
            "coupling.allowables.contact_stress_pa");
}

// Found by fuzz/wire_request_fuzzer: an inline coupling with a 4.8e228 m shaft gave an
// infinite induced moment (self-weight, eq 48), one with a 1e-322 m facewidth an infinite sag
// and restoring torque (eqs 49-53). Sizes, weights and moduli now have physical ranges.
TEST(InputValidation, CouplingSizesOutsideTheirRangesAreRejectedNamingTheField) {
  EXPECT_EQ(coupling_field([](auto& d) { d.shaft_length_m = 4.8241085992082403e228; }),
            "coupling.shaft_length_m");
  EXPECT_EQ(coupling_field([](auto& d) {
              d.facewidth_m = 1e-322;
              d.crown_radius_m = 2.772226230469085e-307;  // > F/2, as the fuzzer gave it
            }),
            "coupling.facewidth_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.facewidth_m = 2000.0; }), "coupling.facewidth_m");
  // Found by fuzz/coupling_text_fuzzer: nrel_upwind with a 5.127 m facewidth (and a 1.836 m
  // outer diameter) validated, and its induced moments at half the jam angle were NaN (eq 39).
  EXPECT_EQ(coupling_field([](auto& d) {
              d.facewidth_m = 5.127;
              d.outer_diameter_m = 1.83632;
            }),
            "coupling.facewidth_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.facewidth_m = d.pitch_diameter_m; }),
            "coupling.facewidth_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.youngs_modulus_pa = 1e300; }),
            "coupling.youngs_modulus_pa");
  EXPECT_EQ(coupling_field([](auto& d) { d.youngs_modulus_pa = 1e-300; }),
            "coupling.youngs_modulus_pa");
  EXPECT_EQ(coupling_field([](auto& d) { d.coupling_weight_n = 1e300; }),
            "coupling.coupling_weight_n");
  EXPECT_EQ(coupling_field([](auto& d) { d.shaft_weight_per_length_n_per_m = 1e300; }),
            "coupling.shaft_weight_per_length_n_per_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.allowables.bending_stress_pa = 1e300; }),
            "coupling.allowables.bending_stress_pa");
  EXPECT_EQ(coupling_field([](auto& d) { d.backlash_m = 1e-300; }), "coupling.backlash_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.outer_diameter_m = 1e300; }),
            "coupling.outer_diameter_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.sleeve_root_diameter_m = 1e300; }),
            "coupling.sleeve_root_diameter_m");
  EXPECT_EQ(coupling_field([](auto& d) { d.crown_radius_m = 1e300; }), "coupling.crown_radius_m");
  // A derived crown radius over 1e4 m is the lead modification's: that field is named.
  EXPECT_EQ(coupling_field([](auto& d) { d.lead_modification_m = 1e-300; }),
            "coupling.lead_modification_m");
  EXPECT_EQ(coupling_field([](auto& d) {
              d.teeth = 8;
              d.module_m = 1e-300;
              d.pitch_diameter_m = 8e-300;
            }),
            "coupling.pitch_diameter_m");
}

TEST(InputValidation, CouplingAtItsLargestWeightsAndShaftGivesFiniteResults) {
  CouplingDefinition d = nrel_upwind();
  d.coupling_weight_n = 1e9;
  d.shaft_weight_per_length_n_per_m = 1e9;
  d.shaft_length_m = 1000.0;
  const CouplingGeometry g(d);
  const OperatingPoint p{1.5e6, 0.5 * g.jam_angle().angle_rad, 0.3, 0.1};
  const InducedMoments m = induced_moments(g, p);
  EXPECT_TRUE(std::isfinite(m.self_weight_moment_nm) && std::isfinite(m.magnitude_nm));
  const RestoringTorque r = restoring_torque(g);
  EXPECT_TRUE(std::isfinite(r.torque_nm) && std::isfinite(r.sag_m));
}

TEST(InputValidation, OperatingPointErrorsNameTheField) {
  const CouplingGeometry g(nrel_upwind());
  const auto contact = [&g](OperatingPoint p) { return [&g, p] { tooth_contact(g, p); }; };
  EXPECT_EQ(field_of(contact({kNaN, 0.0, 0.0, 0.0})), "operating_point.torque_nm");
  EXPECT_EQ(field_of(contact({0.0, 0.0, 0.0, 0.0})), "operating_point.torque_nm");
  EXPECT_EQ(field_of(contact({-1e6, 0.0, 0.0, 0.0})), "operating_point.torque_nm");
  EXPECT_EQ(field_of(contact({1e308, deg(0.3), 0.0, 0.1})), "operating_point.torque_nm");  // overflow
  EXPECT_EQ(field_of(contact({1e6, kNaN, 0.0, 0.0})), "operating_point.misalignment_rad");
  EXPECT_EQ(field_of(contact({1e6, -1e-3, 0.0, 0.0})), "operating_point.misalignment_rad");
  EXPECT_EQ(field_of(contact({1e6, g.jam_angle().angle_rad, 0.0, 0.0})),
            "operating_point.misalignment_rad");  // at the jam angle
  EXPECT_EQ(field_of(contact({1e6, deg(0.3), kInf, 0.0})), "operating_point.direction_rad");
  EXPECT_EQ(field_of(contact({1e6, deg(0.3), 0.0, -0.1})), "operating_point.friction_coefficient");
  EXPECT_EQ(field_of(contact({1e6, deg(0.3), 0.0, kNaN})), "operating_point.friction_coefficient");
  EXPECT_EQ(field_of([&g] { tooth_contact(g, {1e6, deg(0.3), 0.0, 0.0}, {{}, 7}); }),
            "options.slices");
  EXPECT_EQ(field_of([&g] { induced_moments(g, {1e6, deg(0.3), 0.0, 2.0}); }),
            "operating_point.friction_coefficient");
}

TEST(InputValidation, LooseToleranceIsBlamedNotTheTorque) {
  // Issue 9: tolerance 1e308 accepted q = 1 at once, and the tooth loads that then did not add
  // up were blamed on operating_point.torque_nm.
  const CouplingGeometry g(nrel_upwind());
  for (double tolerance : {1e308, 0.5}) {
    ContactOptions options;
    options.load_sharing.tolerance = tolerance;
    EXPECT_EQ(field_of([&] { tooth_contact(g, {1e6, deg(0.3), 0.0, 0.1}, options); }),
              "options.load_sharing.tolerance")
        << tolerance;
    EXPECT_EQ(field_of([&] { induced_moments(g, {1e6, deg(0.3), 0.0, 0.1}, options); }),
              "options.load_sharing.tolerance")
        << tolerance;
  }
}

TEST(InputValidation, ExtremeButValidInputsGiveFiniteResults) {
  const CouplingGeometry g(nrel_upwind());
  for (double torque : {1e5, 1.5e6, 1e9}) {
    for (double fraction : {0.0, 1e-9, 0.5, 0.999999}) {
      const OperatingPoint p{torque, fraction * g.jam_angle().angle_rad, deg(-720.0), 1.0};
      const ToothContact c = tooth_contact(g, p);
      const InducedMoments m = induced_moments(g, p, c);
      EXPECT_TRUE(std::isfinite(c.load_sharing.q) && std::isfinite(c.max_tooth_load_n));
      EXPECT_TRUE(std::isfinite(m.magnitude_nm) && std::isfinite(m.direction_rad));
      EXPECT_TRUE(std::isfinite(c.max_stress.contact_stress_pa));
      for (const ToothLoad& t : c.teeth) ASSERT_TRUE(std::isfinite(t.zone_end_m));
    }
  }
}

TEST(InputValidation, LightTorqueNearTheJamAngleIsRejectedNotSilentlyLost) {
  // At 1 kN·m and 0.4 deg, eq 9 with eq 22's q carries 47 % of P_t (z_e/z_o about 0.001):
  // an error naming the torque, never loads that do not add up to the transmitted torque.
  const CouplingGeometry g(nrel_upwind());
  try {
    tooth_contact(g, {1e3, deg(0.4), 0.0, 0.0});
    FAIL() << "light torque near the jam angle must be rejected";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "operating_point.torque_nm");
    EXPECT_NE(std::string(e.what()).find("eq 9"), std::string::npos);
  }
  // The same point aligned, or at the paper's lowest test torque, is fine.
  EXPECT_EQ(tooth_contact(g, {1e3, 0.0, 0.0, 0.0}).teeth_in_contact, 100);
  const ToothContact low = tooth_contact(g, {1e5, deg(0.74), 0.0, 0.0});
  EXPECT_GT(low.sum_tooth_loads_n / low.total_normal_load_n, 0.98);
  // The floor is an option: at 0 the loads come back, and are reported as they are.
  ContactOptions permissive;
  permissive.min_load_fraction = 0.0;
  const ToothContact lost = tooth_contact(g, {1e3, deg(0.4), 0.0, 0.0}, permissive);
  EXPECT_NEAR(lost.sum_tooth_loads_n / lost.total_normal_load_n, 0.465, 0.005);
}

}  // namespace
}  // namespace gc
