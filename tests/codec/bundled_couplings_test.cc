// The bundled coupling files load to exactly the Table 1 definitions the core tests use
// (tests/core/nrel_couplings.h), so the two cannot drift apart.
#include <gtest/gtest.h>

#include "codec/coupling_file.h"
#include "tests/core/nrel_couplings.h"

namespace gc::codec {
namespace {

void expect_same(const CouplingDefinition& a, const CouplingDefinition& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.teeth, b.teeth);
  const std::pair<double, double> fields[] = {
      {a.module_m, b.module_m},
      {a.pressure_angle_rad, b.pressure_angle_rad},
      {a.pitch_diameter_m, b.pitch_diameter_m},
      {a.base_diameter_m, b.base_diameter_m},
      {a.outer_diameter_m, b.outer_diameter_m},
      {a.root_diameter_m, b.root_diameter_m},
      {a.center_distance_m, b.center_distance_m},
      {a.backlash_m, b.backlash_m},
      {a.tooth_thickness_m, b.tooth_thickness_m},
      {a.tool_tip_radius_m, b.tool_tip_radius_m},
      {a.facewidth_m, b.facewidth_m},
      {a.lead_modification_m, b.lead_modification_m},
      {a.profile_tip_relief_m, b.profile_tip_relief_m},
      {a.profile_relief_start_roll_rad, b.profile_relief_start_roll_rad},
      {a.form_factor_hub, b.form_factor_hub},
      {a.form_factor_sleeve, b.form_factor_sleeve},
      {a.youngs_modulus_pa, b.youngs_modulus_pa},
      {a.poisson_ratio, b.poisson_ratio},
      {a.design_misalignment_rad, b.design_misalignment_rad},
      {a.coupling_weight_n, b.coupling_weight_n},
      {a.shaft_weight_per_length_n_per_m, b.shaft_weight_per_length_n_per_m},
      {a.shaft_length_m, b.shaft_length_m},
      {a.tilt_rad, b.tilt_rad},
      {a.allowables.contact_stress_pa, b.allowables.contact_stress_pa},
      {a.allowables.bending_stress_pa, b.allowables.bending_stress_pa},
  };
  for (std::size_t i = 0; i < std::size(fields); ++i) {
    EXPECT_NEAR(fields[i].first, fields[i].second, 1e-15 * std::abs(fields[i].second) + 1e-18)
        << a.name << " field #" << i;
  }
  EXPECT_EQ(a.crown_radius_m.has_value(), b.crown_radius_m.has_value());
  EXPECT_EQ(a.sleeve_root_diameter_m.has_value(), b.sleeve_root_diameter_m.has_value());
}

TEST(BundledCouplings, FilesEqualTheTable1DefinitionsOfTheCoreTests) {
  const std::string dir = GC_BUNDLED_CATALOG_DIR;
  expect_same(load_coupling_file(dir + "/nrel_upwind.textproto"), gc::testing::nrel_upwind());
  expect_same(load_coupling_file(dir + "/nrel_downwind.textproto"), gc::testing::nrel_downwind());
}

}  // namespace
}  // namespace gc::codec
