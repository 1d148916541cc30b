// The expression effect (core/effects/expression.h): a formula of catalogue terms in a model,
// checked like any effect's parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "core/effects/expression.h"
#include "core/effects/expression_terms.h"
#include "core/model_error.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

std::string field_of(const ParameterValues& values) {
  try {
    make_effect(kExpressionEffect, values);
  } catch (const InvalidInput& e) {
    return e.field() + ": " + e.what();
  }
  return "(accepted)";
}

TEST(ExpressionEffect, RefusesUnknownTermsOutOfBoundCoefficientsAndNothing) {
  EXPECT_EQ(field_of({}).rfind("effects.expression:", 0), 0u) << field_of({});
  const std::string unknown = field_of({{"speed_on_w", 1.0}});
  EXPECT_EQ(unknown.rfind("effects.expression.speed_on_w:", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("speed_on_z"), std::string::npos) << "lists the terms: " << unknown;
  const std::string big = field_of({{"model_z_on_y", 3.0}});  // a cross-talk of 300 %
  EXPECT_EQ(big.rfind("effects.expression.model_z_on_y:", 0), 0u) << big;
  EXPECT_NE(big.find("3"), std::string::npos);
  EXPECT_EQ(field_of({{"constant_on_y", std::nan("")}}).rfind("effects.expression.constant_on_y", 0), 0u);
}

TEST(ExpressionEffect, AddsItsTermsToTheModelsMomentsAfterEveryOtherEffect) {
  const CouplingModel plain(testing::nrel_upwind(), {make_effect("friction")});
  const auto formula = make_expression({{"travel_sign_along_misalignment", 4000.0},
                                        {"model_z_on_y", 0.05},
                                        {"speed_on_z", 300.0}});
  // The formula is added before another effect, and still acts last.
  const CouplingModel with = plain.with_effect(formula).with_effect(make_effect("channel_gain_offset", {{"offset_y_nm", 100.0}}));
  ASSERT_EQ(with.effects().back()->name(), "expression");
  MeasurementSample s;
  s.torque_nm = 1.2e6;
  s.misalignment_rad = 0.004;
  s.direction_rad = 0.3;
  s.loading_direction = -1;
  s.travel_direction = -1;
  s.speed_rpm = 14.0;
  const SensorMoments m = plain.predict(s).moments;
  const SensorMoments f = with.predict(s).moments;
  EXPECT_NEAR(f.y_nm, m.y_nm + 100.0 + 0.05 * m.z_nm - 4000.0 * std::cos(0.3), 1e-6);
  EXPECT_NEAR(f.z_nm, m.z_nm + 300.0 * 14.0 - 4000.0 * std::sin(0.3), 1e-6);
  // A term that reads an input the sample lacks refuses it by name.
  s.speed_rpm.reset();
  try {
    with.predict(s);
    ADD_FAILURE() << "predicted without a speed";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "effects.expression.speed_on_z");
  }
}

TEST(ExpressionEffect, OneTermSetIsOneInfoWhateverTheOrder) {
  const EffectInfo& a = expression_info({"speed_on_z", "constant_on_y"});
  const EffectInfo& b = expression_info({"constant_on_y", "speed_on_z"});
  EXPECT_EQ(&a, &b);
  ASSERT_EQ(a.parameters.size(), 2u);
  EXPECT_EQ(a.parameters[0].name, "constant_on_y");
  EXPECT_EQ(a.parameters[1].unit, "N·m/rpm");
}

TEST(ExpressionTerms, EveryTermHasAUnitABoundAndMechanisms) {
  for (const ExpressionTerm& t : expression_terms()) {
    EXPECT_FALSE(t.coefficient_unit.empty()) << t.name;
    EXPECT_GT(t.bound, 0.0) << t.name;
    EXPECT_GT(t.mechanisms.size(), 40u) << t.name;
    EXPECT_EQ(find_expression_term(t.name), &t);
  }
  // The revolution terms need the rotation phase; the frame terms only the basic inputs.
  MeasurementSample s;
  s.direction_rad = 1.0;
  EXPECT_FALSE(find_expression_term("revolution_sin_on_y")->value(s, {1.0, 2.0}).has_value());
  s.rotation_phase_rad = M_PI / 2;
  EXPECT_NEAR(find_expression_term("revolution_sin_on_y")->value(s, {1.0, 2.0})->x(), 1.0, 1e-12);
  const Eigen::Vector2d normal = *find_expression_term("constant_normal_to_moment")->value(s, {3.0, 4.0});
  EXPECT_NEAR(normal.x(), -0.8, 1e-12);
  EXPECT_NEAR(normal.y(), 0.6, 1e-12);
  const Eigen::Vector2d scaled = *find_expression_term("constant_times_moment")->value(s, {3.0, 4.0});
  EXPECT_NEAR(scaled.x(), 3.0, 1e-12);
  EXPECT_NEAR(scaled.y(), 4.0, 1e-12);
}

// A cycle in time is a term whose period is in its name, made on first use: one spelling per period
// (at most 6 significant digits, no exponent, no trailing zeros), 0.02 s to 1e6 s; others are
// unknown terms, refused by name.
TEST(ExpressionTerms, TimeCycleTermsCarryTheirPeriodInTheirName) {
  const ExpressionTerm* sine = find_expression_term("time_cycle_70s_sin_on_z");
  ASSERT_NE(sine, nullptr);
  EXPECT_EQ(sine, find_expression_term("time_cycle_70s_sin_on_z")) << "one term object per name";
  EXPECT_DOUBLE_EQ(sine->period_s, 70.0);
  EXPECT_EQ(sine->formula, "sin(2 pi t / 70 s) on M_sz'");
  MeasurementSample s;
  s.time_s = 17.5;  // a quarter period
  const Eigen::Vector2d v = *sine->value(s, {1.0, 2.0});
  EXPECT_NEAR(v.x(), 0.0, 1e-12);
  EXPECT_NEAR(v.y(), 1.0, 1e-12);
  EXPECT_NEAR(find_expression_term("time_cycle_70s_cos_on_y")->value(s, {1.0, 2.0})->x(), 0.0, 1e-12);
  for (const char* bad : {"time_cycle_0.00001s_sin_on_y", "time_cycle_070s_sin_on_y", "time_cycle_70.50s_sin_on_y",
                          "time_cycle_70s_tan_on_y", "time_cycle_s_sin_on_y", "time_cycle_2000000s_sin_on_y",
                          "time_cycle_7e1s_sin_on_y", "time_cycle_2.5000001s_sin_on_y", "time_cycle_nans_sin_on_y"}) {
    EXPECT_EQ(find_expression_term(bad), nullptr) << bad;
    EXPECT_EQ(field_of({{bad, 1.0}}).rfind(std::string("effects.expression.") + bad + ":", 0), 0u) << field_of({{bad, 1.0}});
  }
  EXPECT_EQ(cycle_term_names(69.6), (std::vector<std::string>{"time_cycle_69.6s_sin_on_y", "time_cycle_69.6s_cos_on_y",
                                                              "time_cycle_69.6s_sin_on_z", "time_cycle_69.6s_cos_on_z"}));
  // An interference of a fixed frequency: its period to 6 digits, so that its phase holds.
  EXPECT_EQ(cycle_term_names(2.50001234)[0], "time_cycle_2.50001s_sin_on_y");
  const ExpressionTerm* fast = find_expression_term("time_cycle_2.50001s_cos_on_z");
  ASSERT_NE(fast, nullptr);
  EXPECT_DOUBLE_EQ(fast->period_s, 2.50001);
  EXPECT_NE(fast->mechanisms.find("0.399998 Hz"), std::string::npos) << fast->mechanisms;
  // In a model, as any term: the expression adds c sin(2 pi t / P).
  const CouplingModel plain(testing::nrel_upwind(), {make_effect("friction")});
  const CouplingModel with = plain.with_effect(make_expression({{"time_cycle_70s_sin_on_z", 3000.0}}));
  s.torque_nm = 1.2e6;
  s.misalignment_rad = 0.004;
  EXPECT_NEAR(with.predict(s).moments.z_nm, plain.predict(s).moments.z_nm + 3000.0, 1e-6);
}

// Shaft orders 2..4 beside the revolution: sin/cos(k phi_rot) on each channel.
TEST(ExpressionTerms, ShaftOrdersAreHarmonicsOfTheRotationPhase) {
  const ExpressionTerm* order2 = find_expression_term("order_2_sin_on_y");
  ASSERT_NE(order2, nullptr);
  EXPECT_EQ(order2->formula, "sin(2 phi_rot) on M_sy'");
  EXPECT_NE(order2->mechanisms.find("oval"), std::string::npos);
  MeasurementSample s;
  s.rotation_phase_rad = 0.25 * M_PI;  // 2 phi = 90 deg
  EXPECT_NEAR(order2->value(s, {1.0, 2.0})->x(), 1.0, 1e-12);
  EXPECT_NEAR(find_expression_term("order_4_cos_on_z")->value(s, {1.0, 2.0})->y(), -1.0, 1e-12);  // cos(pi)
  EXPECT_EQ(find_expression_term("order_5_sin_on_y"), nullptr);
  s.rotation_phase_rad.reset();
  EXPECT_FALSE(order2->value(s, {1.0, 2.0}).has_value()) << "no speed, no phase, no order";
}

// A step of one channel at a time: its time in its name, 0 before and 1 from it on.
TEST(ExpressionTerms, StepTermsCarryTheirTimeInTheirName) {
  EXPECT_EQ(step_term_names(333.25), (std::vector<std::string>{"step_at_333.25s_on_y", "step_at_333.25s_on_z"}));
  const ExpressionTerm* step = find_expression_term("step_at_333.25s_on_y");
  ASSERT_NE(step, nullptr);
  EXPECT_NE(step->mechanisms.find("re-zeroed"), std::string::npos);
  MeasurementSample s;
  s.time_s = 333.2;
  EXPECT_EQ(*step->value(s, {}), Eigen::Vector2d(0.0, 0.0));
  s.time_s = 333.25;
  EXPECT_EQ(*step->value(s, {}), Eigen::Vector2d(1.0, 0.0));
  for (const char* bad : {"step_at_333.250s_on_y", "step_at_333.25s_on_x", "step_at_s_on_y", "step_at_2e9s_on_z"}) {
    EXPECT_EQ(find_expression_term(bad), nullptr) << bad;
  }
  const CouplingModel plain(testing::nrel_upwind(), {make_effect("friction")});
  const CouplingModel with = plain.with_effect(make_expression({{"step_at_10s_on_z", -4000.0}}));
  s.torque_nm = 1.2e6;
  s.misalignment_rad = 0.004;
  s.time_s = 12.0;
  EXPECT_NEAR(with.predict(s).moments.z_nm, plain.predict(s).moments.z_nm - 4000.0, 1e-6);
  s.time_s = 8.0;
  EXPECT_NEAR(with.predict(s).moments.z_nm, plain.predict(s).moments.z_nm, 1e-6);
}

}  // namespace
}  // namespace gc
