// Every effect: neutral at its neutral value, and changing the model the way its physics says.
#include <gtest/gtest.h>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "core/effects/expression.h"
#include "core/induced_moments.h"
#include "core/model_error.h"
#include "core/restoring_torque.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::deg;
using testing::nrel_upwind;

std::shared_ptr<const Effect> paper_friction(double mu) { return make_effect("friction", {{"mu0", mu}}); }

CouplingModel paper_model(double mu = 0.1) {
  return CouplingModel(nrel_upwind(), {paper_friction(mu), make_effect("pressure_angle_rotation"),
                                       make_effect("self_weight")});
}

MeasurementSample sample(double torque, double zeta_deg, double beta_deg = 30.0, int loading = 0) {
  MeasurementSample s;
  s.torque_nm = torque;
  s.misalignment_rad = deg(zeta_deg);
  s.direction_rad = deg(beta_deg);
  s.loading_direction = loading;
  return s;
}

SensorMoments predict(const CouplingModel& model, const MeasurementSample& s) {
  return model.predict(s).moments;
}

double magnitude(const SensorMoments& m) { return std::hypot(m.y_nm, m.z_nm); }

TEST(Effects, PaperConfigurationReproducesEq48Exactly) {
  const CouplingModel model = paper_model(0.12);
  const MeasurementSample s = sample(1.2e6, 0.4, 70.0);
  const InducedMoments direct =
      induced_moments(model.geometry(), {1.2e6, deg(0.4), deg(70.0), 0.12});
  const SensorMoments m = predict(model, s);
  EXPECT_NEAR(m.y_nm, direct.sensor_moment_y_nm, 1e-6);
  EXPECT_NEAR(m.z_nm, direct.sensor_moment_z_nm, 1e-6);
}

TEST(Effects, EveryEffectAtItsNeutralValuesChangesNothing) {
  const CouplingModel base = paper_model();
  for (const EffectRegistration& r : effect_registry()) {
    if (r.info->parameters.empty() && r.info->name != kExpressionEffect) continue;  // a switch: no neutral value
    ParameterValues neutral;
    for (const ParameterSpec& p : r.info->parameters) neutral[p.name] = p.neutral;
    // The formula's parameters are the terms it is given: two of them, at zero.
    if (r.info->name == kExpressionEffect) neutral = {{"constant_on_y", 0.0}, {"travel_sign_along_moment", 0.0}};
    const auto effect = r.make(neutral);
    EXPECT_TRUE(effect->neutral()) << r.info->name;
    const CouplingModel with = base.with_effect(effect);
    for (const MeasurementSample& s : {sample(1.5e6, 0.4, 30, +1), sample(0.2e6, 0.1, 200, -1)}) {
      const SensorMoments b = predict(with, s);
      if (r.info->name == "friction" || r.info->name == "self_weight" ||
          r.info->name == "pressure_angle_rotation") {
        // The paper's own effects: neutral means "as if absent" from a model without them.
        std::vector<std::shared_ptr<const Effect>> others;
        for (const auto& e : base.effects()) if (e->name() != r.info->name) others.push_back(e);
        const CouplingModel without(nrel_upwind(), others);
        const SensorMoments c = predict(without, s);
        EXPECT_NEAR(b.y_nm, c.y_nm, 1e-6) << r.info->name;
        EXPECT_NEAR(b.z_nm, c.z_nm, 1e-6) << r.info->name;
      } else {
        EXPECT_NEAR(b.y_nm, predict(base, s).y_nm, 1e-6) << r.info->name;
        EXPECT_NEAR(b.z_nm, predict(base, s).z_nm, 1e-6) << r.info->name;
      }
    }
  }
}

TEST(Effects, FrictionRaisesTheMomentsAndItsTermsFollowTorqueAndMisalignment) {
  const auto model = [](ParameterValues v) {
    return CouplingModel(nrel_upwind(), {make_effect("friction", v), make_effect("pressure_angle_rotation")});
  };
  const CouplingModel low = model({{"mu0", 0.05}});
  const CouplingModel high = model({{"mu0", 0.15}});
  EXPECT_GT(magnitude(predict(high, sample(1.5e6, 0.4))), 1.3 * magnitude(predict(low, sample(1.5e6, 0.4))));
  // mu_low_torque: the friction it adds is T_ref / T times its coefficient.
  const CouplingModel rising = model({{"mu0", 0.05}, {"mu_low_torque", 0.02}});
  EXPECT_NEAR(rising.predict(sample(0.3e6, 0.4)).state.point.friction_coefficient, 0.05 + 0.02 * 5.0, 1e-12);
  EXPECT_NEAR(rising.predict(sample(1.5e6, 0.4)).state.point.friction_coefficient, 0.07, 1e-12);
  // mu_misalignment: proportional to zeta over the jam angle.
  const CouplingModel angled = model({{"mu0", 0.05}, {"mu_misalignment", 0.1}});
  const double jam = angled.geometry().jam_angle().angle_rad;
  const MeasurementSample half = sample(1.5e6, testing::to_deg(0.5 * jam));
  EXPECT_NEAR(angled.predict(half).state.point.friction_coefficient, 0.05 + 0.05, 1e-12);
}

TEST(Effects, SelfWeightShiftsOnlyMsyByTheWeightMoment) {
  const CouplingModel base(nrel_upwind(), {paper_friction(0.1)});
  const MeasurementSample s = sample(1.5e6, 0.4);
  for (double scale : {1.0, 2.0}) {
    const SensorMoments m = predict(base.with_effect(make_effect("self_weight", {{"weight_scale", scale}})), s);
    EXPECT_NEAR(m.y_nm, predict(base, s).y_nm - scale * 149912.0, 1e-6);
    EXPECT_NEAR(m.z_nm, predict(base, s).z_nm, 1e-9);
  }
}

TEST(Effects, PressureAngleRotationTurnsTheMomentByPhi) {
  const CouplingModel base(nrel_upwind(), {paper_friction(0.1)});
  const MeasurementSample s = sample(1.5e6, 0.4, 10.0);
  const SensorMoments a = predict(base, s);
  for (double scale : {0.5, 1.0}) {
    const SensorMoments b =
        predict(base.with_effect(make_effect("pressure_angle_rotation", {{"shift_scale", scale}})), s);
    EXPECT_NEAR(magnitude(a), magnitude(b), 1e-6);
    // Eqs 44-45 turn (M_y', M_z') clockwise by the shift.
    const double turned = std::remainder(std::atan2(a.z_nm, a.y_nm) - std::atan2(b.z_nm, b.y_nm), 2 * M_PI);
    EXPECT_NEAR(turned, scale * deg(20.0), 1e-12);
  }
}

TEST(Effects, AssemblyMisalignmentActsLikeAMeasuredOne) {
  const CouplingModel base = paper_model();
  const CouplingModel with = base.with_effect(
      make_effect("assembly_misalignment", {{"zeta0_rad", deg(0.2)}, {"beta0_rad", deg(90)}}));
  // Measured 0.2 deg at 0 deg plus 0.2 deg at 90 deg: 0.2 sqrt(2) deg at 45 deg.
  const SensorMoments m = predict(with, sample(1.5e6, 0.2, 0.0));
  const SensorMoments expected = predict(base, sample(1.5e6, 0.2 * std::sqrt(2.0), 45.0));
  EXPECT_NEAR(m.y_nm, expected.y_nm, 1e-6);
  EXPECT_NEAR(m.z_nm, expected.z_nm, 1e-6);
  // At zero measured misalignment the coupling still sees zeta0.
  EXPECT_NEAR(with.predict(sample(1.5e6, 0.0)).state.point.misalignment_rad, deg(0.2), 1e-15);
}

TEST(Effects, EccentricityFadesLinearlyUpToTheRestoringTorque) {
  const CouplingModel base = paper_model();
  const CouplingModel with = base.with_effect(make_effect("eccentricity", {{"eccentric_misalignment_rad", deg(0.06)}}));
  const double t_m = restoring_torque(with.geometry()).torque_nm;  // eqs 49-53: 1.36 MN·m
  // Aligned measurement: the coupling sees zeta_e (1 - T / T_m) in the gravity direction.
  EXPECT_NEAR(with.predict(sample(0.25 * t_m, 0.0)).state.point.misalignment_rad, deg(0.06) * 0.75, 1e-9);
  EXPECT_NEAR(with.predict(sample(0.25 * t_m, 0.0)).state.point.direction_rad, M_PI / 2, 1e-12);
  EXPECT_NEAR(with.predict(sample(0.75 * t_m, 0.0)).state.point.misalignment_rad, deg(0.06) * 0.25, 1e-9);
  // At and above T_m nothing changes.
  const MeasurementSample above = sample(1.5e6, 0.3);
  EXPECT_EQ(predict(with, above).y_nm, predict(base, above).y_nm);
}

TEST(Effects, ComplianceSpreadsTheLoadOverMoreTeeth) {
  const MeasurementSample s = sample(1.5e6, 0.5);
  const CouplingModel stiff = paper_model();
  const CouplingModel soft = stiff.with_effect(make_effect("compliance", {{"stiffness_factor", 0.5}}));
  EXPECT_NEAR(soft.geometry().mesh_stiffness_n_per_m(), 0.5 * stiff.geometry().mesh_stiffness_n_per_m(), 1e-3);
  const ToothContact a = tooth_contact(stiff.geometry(), stiff.predict(s).state.point);
  const ToothContact b = tooth_contact(soft.geometry(), soft.predict(s).state.point);
  EXPECT_GT(b.teeth_in_contact, a.teeth_in_contact);
  EXPECT_LT(b.max_tooth_load_n, a.max_tooth_load_n);
}

TEST(Effects, SpacingErrorsConcentrateTheLoadEvenWhenAligned) {
  const CouplingModel base = paper_model();
  const CouplingModel with = base.with_effect(make_effect("spacing_errors", {{"spacing_error_m", 5e-5}}));
  // z_o = 50 um against z_e of about 21-60 um: eq 9 unloads the teeth far from z''.
  const ModelPrediction p = with.predict(sample(1.5e6, 0.0));
  EXPECT_DOUBLE_EQ(p.state.contact.spacing_error_m, 5e-5);
  const ToothContact c = tooth_contact(with.geometry(), p.state.point, p.state.contact);
  EXPECT_LT(c.load_sharing.q, 1.0);
  EXPECT_LT(c.teeth_in_contact, 100);
}

TEST(Effects, ChannelGainAndOffsetAreAffine) {
  const CouplingModel base = paper_model();
  const CouplingModel with = base.with_effect(make_effect(
      "channel_gain_offset", {{"gain_y", 0.05}, {"gain_z", -0.1}, {"offset_y_nm", 2e4}, {"offset_z_nm", -3e4}}));
  const MeasurementSample s = sample(1.0e6, 0.3);
  EXPECT_NEAR(predict(with, s).y_nm, 1.05 * predict(base, s).y_nm + 2e4, 1e-6);
  EXPECT_NEAR(predict(with, s).z_nm, 0.9 * predict(base, s).z_nm - 3e4, 1e-6);
}

// The lag follows the last travel, held through a hold (the friction keeps the coupling where it
// stuck), not whether the misalignment is moving at this sample.
MeasurementSample travelled(double torque, double zeta_deg, int travel, int loading) {
  MeasurementSample s = sample(torque, zeta_deg, 0, loading);
  s.travel_direction = travel;
  return s;
}

TEST(Effects, HysteresisLagsTheMisalignmentAgainstItsLastTravelThroughAHold) {
  const CouplingModel with = paper_model().with_effect(make_effect("hysteresis", {{"lag_rad", deg(0.02)}}));
  const auto seen = [&](int travel, int loading) {
    return with.predict(travelled(1.5e6, 0.4, travel, loading)).state.point.misalignment_rad;
  };
  EXPECT_NEAR(seen(+1, +1), deg(0.38), 1e-12);  // rising
  EXPECT_NEAR(seen(-1, -1), deg(0.42), 1e-12);  // falling
  EXPECT_NEAR(seen(+1, 0), deg(0.38), 1e-12);   // held after a rise
  EXPECT_NEAR(seen(-1, 0), deg(0.42), 1e-12);   // held after a fall
  EXPECT_NEAR(seen(0, 0), deg(0.40), 1e-12);    // before any travel
  // Falling, the coupling sees what the paper's model sees at zeta + lag.
  const SensorMoments falling = predict(with, travelled(1.5e6, 0.4, -1, -1));
  const SensorMoments lagged = predict(paper_model(), sample(1.5e6, 0.42, 0, 0));
  EXPECT_NEAR(falling.y_nm, lagged.y_nm, 1e-6);
  EXPECT_NEAR(falling.z_nm, lagged.z_nm, 1e-6);
}

TEST(Effects, MisalignmentScaleShowsTheCouplingMoreMisalignmentThanMeasured) {
  const CouplingModel with = paper_model().with_effect(make_effect("misalignment_scale", {{"scale_error", 0.15}}));
  EXPECT_NEAR(with.predict(sample(1.2e6, 0.4)).state.point.misalignment_rad, deg(0.46), 1e-12);
  const SensorMoments scaled = predict(with, sample(1.2e6, 0.4));
  const SensorMoments seen = predict(paper_model(), sample(1.2e6, 0.46));
  EXPECT_NEAR(scaled.y_nm, seen.y_nm, 1e-6);
  EXPECT_NEAR(scaled.z_nm, seen.z_nm, 1e-6);
}

// The transducer reads T; the coupling carries T (1 + k + c T / 1 MN·m), and the model computes
// with that torque.
TEST(Effects, TorqueCalibrationGivesTheCouplingTheTorqueItCarries) {
  const CouplingModel with =
      paper_model().with_effect(make_effect("torque_calibration", {{"slope_error", 0.01}, {"curvature_per_mnm", -0.02}}));
  EXPECT_NEAR(with.predict(sample(1.5e6, 0.4)).state.point.torque_nm, 1.5e6 * (1.0 + 0.01 - 0.02 * 1.5), 1e-6);
  const SensorMoments calibrated = predict(with, sample(1.5e6, 0.4));
  const SensorMoments carried = predict(paper_model(), sample(1.5e6 * 0.98, 0.4));
  EXPECT_NEAR(calibrated.y_nm, carried.y_nm, 1e-6);
  EXPECT_NEAR(calibrated.z_nm, carried.z_nm, 1e-6);
}

// 60 urad/deg C above 35 deg C along +z (beta = 90 deg): at 55 deg C the coupling sees the
// measured vector plus 1.2 mrad along z; at 35 deg C nothing; without a temperature nothing.
TEST(Effects, ThermalMisalignmentAddsGrowthInProportionToTheTemperatureRise) {
  const CouplingModel with = paper_model().with_effect(make_effect(
      "thermal_misalignment", {{"growth_rad_per_c", 6e-5}, {"reference_temperature_c", 35.0}, {"direction_rad", M_PI / 2}}));
  MeasurementSample warm = sample(1.2e6, 0.4, 0.0);
  warm.temperature_c = 55.0;
  const OperatingPoint seen = with.predict(warm).state.point;
  EXPECT_NEAR(seen.misalignment_rad, std::hypot(deg(0.4), 1.2e-3), 1e-12);
  EXPECT_NEAR(seen.direction_rad, std::atan2(1.2e-3, deg(0.4)), 1e-12);
  MeasurementSample aligned = warm;
  aligned.temperature_c = 35.0;
  EXPECT_NEAR(with.predict(aligned).state.point.misalignment_rad, deg(0.4), 1e-15);
  EXPECT_NEAR(with.predict(sample(1.2e6, 0.4, 0.0)).state.point.misalignment_rad, deg(0.4), 1e-15);
}

TEST(Effects, ContinuousQuarterSumsIsTheContactOptionAsAModelPart) {
  const auto switched = make_effect("continuous_quarter_sums");
  EXPECT_FALSE(switched->neutral());
  ContactOptions continuous;
  continuous.continuous_quarter_sums = true;
  std::vector<std::shared_ptr<const Effect>> effects = paper_model().effects();
  const CouplingModel with_option(nrel_upwind(), effects, continuous);
  const CouplingModel with_effect = paper_model().with_effect(switched);
  for (double torque : {0.3e6, 0.571e6, 1.2e6}) {
    const MeasurementSample s = sample(torque, 0.3);
    EXPECT_EQ(predict(with_effect, s).y_nm, predict(with_option, s).y_nm);
    EXPECT_EQ(predict(with_effect, s).z_nm, predict(with_option, s).z_nm);
  }
  EXPECT_NE(predict(with_effect, sample(0.56e6, 0.3)).y_nm, predict(paper_model(), sample(0.56e6, 0.3)).y_nm);
}

// Its one parameter scales the change from the paper's form to the continuous one: 0 is the
// paper's sawtooth, 1 the continuous form, between a sawtooth partly smoothed, beyond 1 a
// recording whose steps at the quarter-sum crossings are turned over.
TEST(Effects, ContinuousQuarterSumsScalesTheSawtoothsChange) {
  ContactOptions continuous;
  continuous.continuous_quarter_sums = true;
  const CouplingModel smooth(nrel_upwind(), paper_model().effects(), continuous);
  EXPECT_TRUE(make_effect("continuous_quarter_sums", {{"smoothed_share", 0.0}})->neutral());
  for (double share : {0.0, 0.5, 2.5, -1.0}) {
    const CouplingModel with = paper_model().with_effect(make_effect("continuous_quarter_sums", {{"smoothed_share", share}}));
    for (double torque : {0.3e6, 0.56e6, 1.2e6}) {
      const MeasurementSample s = sample(torque, 0.3);
      const SensorMoments paper = predict(paper_model(), s), even = predict(smooth, s), got = predict(with, s);
      const double tolerance = 1e-9 * std::hypot(paper.y_nm, paper.z_nm);
      EXPECT_NEAR(got.y_nm, paper.y_nm + share * (even.y_nm - paper.y_nm), tolerance) << share << " " << torque;
      EXPECT_NEAR(got.z_nm, paper.z_nm + share * (even.z_nm - paper.z_nm), tolerance) << share << " " << torque;
    }
  }
  // A model on the continuous form counts as share 1: the effect at 0 puts the paper's saw back.
  const CouplingModel back = smooth.with_effect(make_effect("continuous_quarter_sums", {{"smoothed_share", 0.0}}));
  const MeasurementSample s = sample(0.56e6, 0.3);
  EXPECT_NEAR(predict(back, s).y_nm, predict(paper_model(), s).y_nm, 1e-9 * std::abs(predict(paper_model(), s).y_nm));
  EXPECT_THROW(make_effect("continuous_quarter_sums", {{"smoothed_share", 25.0}}), InvalidInput);
}

TEST(Effects, BadConfigurationsNameTheField) {
  const auto field = [](auto call) {
    try { call(); } catch (const InvalidInput& e) { return e.field(); }
    return std::string("(accepted)");
  };
  EXPECT_EQ(field([] { make_effect("teleportation"); }), "effects.teleportation");
  EXPECT_EQ(field([] { make_effect("friction", {{"mu_zero", 0.1}}); }), "effects.friction.mu_zero");
  EXPECT_EQ(field([] { make_effect("friction", {{"mu0", 0.9}}); }), "effects.friction.mu0");
  EXPECT_EQ(field([] { make_effect("hysteresis", {{"lag_rad", std::nan("")}}); }), "effects.hysteresis.lag_rad");
  EXPECT_EQ(field([] { CouplingModel(nrel_upwind(), {make_effect("self_weight"), make_effect("self_weight")}); }),
            "effects.self_weight");
}

TEST(Effects, EffectivelyJammedSampleIsAnErrorNotAValue) {
  const CouplingModel with = paper_model().with_effect(
      make_effect("assembly_misalignment", {{"zeta0_rad", deg(0.28)}}));
  EXPECT_THROW(with.predict(sample(1.5e6, 0.6, 0.0)), InvalidInput);
}

}  // namespace
}  // namespace gc
