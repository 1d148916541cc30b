// The worked example of docs/adding-an-effect.md works as the document says.
#include <gtest/gtest.h>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "core/model_error.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
EffectRegistration temperature_friction_effect();  // tests/core/example_effect/
namespace {

MeasurementSample warm_sample(double temperature_c) {
  MeasurementSample s;
  s.torque_nm = 1.5e6;
  s.misalignment_rad = testing::deg(0.4);
  s.temperature_c = temperature_c;
  return s;
}

CouplingModel paper_with(std::shared_ptr<const Effect> extra) {
  std::vector<std::shared_ptr<const Effect>> effects = {
      make_effect("friction", {{"mu0", 0.1}}), make_effect("pressure_angle_rotation"),
      make_effect("self_weight")};
  if (extra) effects.push_back(std::move(extra));
  return CouplingModel(testing::nrel_upwind(), effects);
}

TEST(ExampleEffect, TemperatureFrictionChangesMuAsDocumented) {
  const EffectRegistration example = temperature_friction_effect();
  const CouplingModel model = paper_with(example.make({{"dmu_dT_per_k", -0.001}}));
  EXPECT_NEAR(model.predict(warm_sample(60.0)).state.point.friction_coefficient, 0.1 - 0.02, 1e-15);
  EXPECT_NEAR(model.predict(warm_sample(20.0)).state.point.friction_coefficient, 0.1 + 0.02, 1e-15);
  // Colder oil, more friction, larger moments.
  const SensorMoments cold = model.predict(warm_sample(20.0)).moments;
  const SensorMoments warm = model.predict(warm_sample(60.0)).moments;
  EXPECT_GT(std::abs(cold.z_nm), std::abs(warm.z_nm));
}

TEST(ExampleEffect, NeutralAtReferenceTemperatureAndZeroSlope) {
  const EffectRegistration example = temperature_friction_effect();
  const CouplingModel base = paper_with(nullptr);
  const CouplingModel at_reference = paper_with(example.make({}));
  EXPECT_EQ(at_reference.predict(warm_sample(40.0)).moments.y_nm,
            base.predict(warm_sample(40.0)).moments.y_nm);
  EXPECT_TRUE(example.make({{"dmu_dT_per_k", 0.0}})->neutral());
}

TEST(ExampleEffect, MissingTemperatureChannelIsNamed) {
  const CouplingModel model = paper_with(temperature_friction_effect().make({}));
  MeasurementSample s = warm_sample(40.0);
  s.temperature_c.reset();
  try {
    model.predict(s);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "sample.temperature_c");
  }
}

TEST(ExampleEffect, IsNotPartOfTheLibrary) {
  EXPECT_THROW(make_effect("temperature_friction"), InvalidInput);
}

}  // namespace
}  // namespace gc
