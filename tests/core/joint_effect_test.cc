// Several effects fitted as one (core/effects/joint_effect.h): the same model as the effects
// themselves, parameters named "<effect>.<parameter>", never held by a model itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "core/effects/joint_effect.h"
#include "core/model_error.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

const EffectRegistration& registration(const std::string& name) {
  const auto& all = effect_registry();
  const auto it = std::find_if(all.begin(), all.end(), [&](const EffectRegistration& r) { return r.info->name == name; });
  EXPECT_NE(it, all.end()) << name;
  return *it;
}

MeasurementSample sample() {
  MeasurementSample s;
  s.torque_nm = 1.5e6;
  s.misalignment_rad = 0.004;
  s.direction_rad = 0.3;
  s.temperature_c = 52.0;
  return s;
}

TEST(JointEffect, PutsItsMembersInTheModelAndPredictsAsThey) {
  const CouplingModel paper(testing::nrel_upwind(), {make_effect("friction", {{"mu0", 0.1}}),
                                                      make_effect("pressure_angle_rotation"), make_effect("self_weight")});
  const EffectRegistration joint =
      joint_registration({registration("thermal_misalignment"), registration("channel_gain_offset")});
  EXPECT_EQ(joint.info->name, "thermal_misalignment+channel_gain_offset");
  const auto effect = joint.make({{"thermal_misalignment.growth_rad_per_c", 6e-5},
                                  {"thermal_misalignment.reference_temperature_c", 35.0},
                                  {"thermal_misalignment.direction_rad", 1.57},
                                  {"channel_gain_offset.offset_y_nm", -10080.0}});
  const CouplingModel together = paper.with_effect(effect);
  const CouplingModel one_by_one =
      paper.with_effect(make_effect("thermal_misalignment", {{"growth_rad_per_c", 6e-5},
                                                             {"reference_temperature_c", 35.0},
                                                             {"direction_rad", 1.57}}))
          .with_effect(make_effect("channel_gain_offset", {{"offset_y_nm", -10080.0}}));
  EXPECT_FALSE(together.has_effect(joint.info->name));
  EXPECT_TRUE(together.has_effect("thermal_misalignment"));
  EXPECT_TRUE(together.has_effect("channel_gain_offset"));
  EXPECT_EQ(together.effects().size(), one_by_one.effects().size());
  const SensorMoments a = together.predict(sample()).moments, b = one_by_one.predict(sample()).moments;
  EXPECT_DOUBLE_EQ(a.y_nm, b.y_nm);
  EXPECT_DOUBLE_EQ(a.z_nm, b.z_nm);
  // The thermal growth and the offset are both there: 17 deg C over the reference turns the
  // moment, and the offset moves M_sy'.
  const SensorMoments bare = paper.predict(sample()).moments;
  EXPECT_GT(std::abs(a.z_nm - bare.z_nm), 100.0);
  // A joint effect given again replaces the members it names, in place of adding beside them.
  const CouplingModel again = together.with_effect(effect);
  EXPECT_EQ(again.effects().size(), together.effects().size());
  EXPECT_DOUBLE_EQ(again.predict(sample()).moments.y_nm, a.y_nm);
}

TEST(JointEffect, ValuesRoundTripByPrefixedName) {
  const std::vector<std::shared_ptr<const Effect>> effects = {
      make_effect("thermal_misalignment", {{"growth_rad_per_c", 5e-5}}),
      make_effect("channel_gain_offset", {{"gain_z", 0.02}})};
  const ParameterValues values = joint_values(effects);
  EXPECT_DOUBLE_EQ(values.at("thermal_misalignment.growth_rad_per_c"), 5e-5);
  EXPECT_DOUBLE_EQ(values.at("channel_gain_offset.gain_z"), 0.02);
  const EffectRegistration joint =
      joint_registration({registration("thermal_misalignment"), registration("channel_gain_offset")});
  const auto effect = joint.make(values);
  ASSERT_EQ(effect->members().size(), 2u);
  EXPECT_DOUBLE_EQ(effect->members()[0]->value("growth_rad_per_c"), 5e-5);
  EXPECT_DOUBLE_EQ(effect->members()[1]->value("gain_z"), 0.02);
  EXPECT_TRUE(make_effect("friction")->members().empty());
}

TEST(JointEffect, RefusesOneEffectTwiceOrAloneAndAValueOutOfBoundsByName) {
  EXPECT_THROW(joint_registration({registration("friction"), registration("friction")}), InvalidInput);
  EXPECT_THROW(joint_registration({registration("friction")}), InvalidInput);
  const EffectRegistration joint = joint_registration({registration("friction"), registration("channel_gain_offset")});
  try {
    joint.make({{"friction.mu0", -1.0}});
    ADD_FAILURE() << "a negative friction coefficient was taken";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "effects.friction+channel_gain_offset.friction.mu0");
  }
  EXPECT_THROW(joint.make({{"mu0", 0.1}}), InvalidInput);  // not prefixed: no such parameter
}

// Put in a model directly (as its comment allows), a joint effect times the inputs and reads their
// history as its members do: a moment_delay inside it delays and averages the inputs in predict_at.
TEST(JointEffect, TimesTheInputsAsItsMembersDoWhenHeldDirectly) {
  const EffectRegistration joint = joint_registration({registration("moment_delay"), registration("channel_gain_offset")});
  const auto effect = joint.make({{"moment_delay.delay_s", -0.4},
                                  {"moment_delay.averaging_revolutions", 0.5},
                                  {"channel_gain_offset.offset_y_nm", 2000.0}});
  EXPECT_TRUE(effect->times_inputs());
  const CouplingModel direct(testing::nrel_upwind(), {make_effect("friction", {{"mu0", 0.1}}), effect});
  const CouplingModel expanded =
      CouplingModel(testing::nrel_upwind(), {make_effect("friction", {{"mu0", 0.1}})}).with_effect(effect);
  ASSERT_EQ(expanded.effects().size(), 3u);
  std::vector<MeasurementSample> ramp(40, sample());
  for (std::size_t k = 0; k < ramp.size(); ++k) {
    ramp[k].time_s = 0.1 * static_cast<double>(k);
    ramp[k].torque_nm = 1.0e6 + 2.0e4 * static_cast<double>(k);
    ramp[k].speed_rpm = 30.0;  // 0.5 revolutions: a 1 s average
  }
  const InputTiming timing = direct.input_timing(ramp[20]);
  EXPECT_DOUBLE_EQ(timing.delay_s, -0.4);
  EXPECT_DOUBLE_EQ(timing.average_s, 1.0);
  const SensorMoments a = direct.predict_at(ramp, 20).moments, b = expanded.predict_at(ramp, 20).moments;
  EXPECT_DOUBLE_EQ(a.y_nm, b.y_nm);
  EXPECT_DOUBLE_EQ(a.z_nm, b.z_nm);
  // The inputs were read from the window (2.4 - 1, 2.4] s, not at t = 2 s.
  const SensorMoments undelayed = expanded.without_effect("moment_delay").predict_at(ramp, 20).moments;
  EXPECT_GT(std::abs(a.y_nm - undelayed.y_nm) + std::abs(a.z_nm - undelayed.z_nm), 1.0);
}

}  // namespace
}  // namespace gc
