// Checks of the generalisation harness itself, so that a failure of gc_generalisation_tests is the
// diagnosis's and not the harness's: the noise has the statistics it claims, the truths' own
// physics agrees with the library where both describe the same thing, and the SINDy baseline
// recovers a sparse residual it can express.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/effects/effect_registry.h"
#include "core/induced_moments.h"
#include "diagnosis/synthesis/load_sequence.h"
#include "tests/diagnosis/independent/base_models.h"
#include "tests/diagnosis/independent/recording_inputs.h"
#include "tests/diagnosis/independent/sindy_baseline.h"
#include "tests/diagnosis/independent/test_cell_noise.h"
#include "tests/diagnosis/independent/truth_physics.h"

namespace gc::independent {
namespace {

struct Moments {
  double mean = 0.0, sd = 0.0, lag1 = 0.0;
};

Moments channel_moments(const ChannelNoise& noise) {
  Moments m;
  const double n = static_cast<double>(noise.size());
  for (const SensorMoments& s : noise) m.mean += s.y_nm / n;
  double var = 0.0, cov = 0.0;
  for (std::size_t i = 0; i < noise.size(); ++i) {
    var += (noise[i].y_nm - m.mean) * (noise[i].y_nm - m.mean) / n;
    if (i > 0) cov += (noise[i].y_nm - m.mean) * (noise[i - 1].y_nm - m.mean) / n;
  }
  m.sd = std::sqrt(var);
  m.lag1 = cov / var;
  return m;
}

// 200,000 samples: the standard error of the sample sd is 0.16 % of sigma for white noise and
// about 0.5 % for phi 0.8, so 2 % tolerances are wide of chance.
TEST(TestCellNoise, WhiteNoiseHasTheGivenSigmaAndNoMemory) {
  const Moments m = channel_moments(white_noise(200000, 2000.0, 3));
  EXPECT_NEAR(m.mean, 0.0, 20.0);
  EXPECT_NEAR(m.sd, 2000.0, 40.0);
  EXPECT_NEAR(m.lag1, 0.0, 0.01);
}

TEST(TestCellNoise, Ar1NoiseHasTheMarginalSigmaAndTheLagOneCorrelationPhi) {
  const Moments m = channel_moments(ar1_noise(200000, 0.8, 2000.0, 5));
  EXPECT_NEAR(m.sd, 2000.0, 40.0);
  EXPECT_NEAR(m.lag1, 0.8, 0.01);
}

TEST(TestCellNoise, SpikyNoiseHasOnePercentOutliersAtTenSigma) {
  const ChannelNoise noise = spiky_noise(200000, 2000.0, 0.01, 10.0, 9);
  int spikes = 0;
  for (const SensorMoments& s : noise) spikes += std::abs(s.y_nm) > 12000.0;  // 6 sigma: no white value
  EXPECT_NEAR(spikes / 200000.0, 0.01, 0.001);
}

TEST(TestCellNoise, TheSameSeedGivesTheSameNoiseAndAnotherSeedOther) {
  EXPECT_EQ(ar1_noise(10, 0.8, 1.0, 4)[9].z_nm, ar1_noise(10, 0.8, 1.0, 4)[9].z_nm);
  EXPECT_NE(ar1_noise(10, 0.8, 1.0, 4)[9].z_nm, ar1_noise(10, 0.8, 1.0, 5)[9].z_nm);
}

// Where the truths' own forms and the library describe the same physics they must agree to
// rounding: the forms differ in the hidden cases, not in how the model is evaluated.
TEST(TruthPhysics, AFrictionChangeAtTheContactMatchesTheLibrarysFrictionOfTheSameLaw) {
  const CouplingModel base = paper_model();
  const double jam = base.geometry().jam_angle().angle_rad;
  const CouplingModel library = base.with_effect(
      make_effect("friction", {{"mu0", 0.1}, {"mu_low_torque", 0.02}, {"mu_misalignment", 0.05}}));
  for (const MeasurementSample& s : recording_inputs(LoadSequenceKind::moment_sweep)) {
    if (s.misalignment_rad < 1e-4) continue;
    const SensorMoments own = with_contact_change(base, s, [jam](OperatingPoint& p, double&) {
      p.friction_coefficient = 0.1 + 0.02 * 1.5e6 / p.torque_nm + 0.05 * p.misalignment_rad / jam;
    });
    const SensorMoments lib = library.predict(s).moments;
    ASSERT_NEAR(own.y_nm, lib.y_nm, 1e-6 * std::abs(lib.y_nm) + 1e-6);
    ASSERT_NEAR(own.z_nm, lib.z_nm, 1e-6 * std::abs(lib.z_nm) + 1e-6);
  }
}

TEST(TruthPhysics, AnAddedMisalignmentVectorMatchesTheLibrarysAssemblyMisalignment) {
  const CouplingModel base = paper_model();
  const CouplingModel library =
      base.with_effect(make_effect("assembly_misalignment", {{"zeta0_rad", 0.002}, {"beta0_rad", 2.0}}));
  for (const MeasurementSample& s : recording_inputs(LoadSequenceKind::moment_sweep)) {
    const SensorMoments own = base.predict(with_added_misalignment(s, 0.002, 2.0)).moments;
    const SensorMoments lib = library.predict(s).moments;
    ASSERT_NEAR(own.y_nm, lib.y_nm, 1e-6 * std::abs(lib.y_nm) + 1e-6);
    ASSERT_NEAR(own.z_nm, lib.z_nm, 1e-6 * std::abs(lib.z_nm) + 1e-6);
  }
}

TEST(TruthPhysics, ATurnOfTheFrameByPhiMatchesTheLibrarysPressureAngleRotation) {
  const CouplingModel without = paper_model("pressure_angle_rotation"), with = paper_model();
  const double phi = without.geometry().pressure_angle_rad();
  for (const MeasurementSample& s : recording_inputs(LoadSequenceKind::moment_sweep)) {
    if (s.misalignment_rad < 1e-4) continue;
    const SensorMoments own = with_contact_change(without, s, [phi](OperatingPoint&, double& shift) { shift += phi; });
    const SensorMoments lib = with.predict(s).moments;
    ASSERT_NEAR(own.y_nm, lib.y_nm, 1e-6 * std::abs(lib.y_nm) + 1e-6);
    ASSERT_NEAR(own.z_nm, lib.z_nm, 1e-6 * std::abs(lib.z_nm) + 1e-6);
  }
}

TEST(TruthPhysics, TheWeightMomentByItsOwnStaticsIsEq48s) {
  const CouplingModel base = paper_model();
  EXPECT_NEAR(weight_moment_nm(base.base_coupling()), self_weight_moment_nm(base.geometry()), 1e-6);
}

// A residual the library expresses exactly (5 kN·m T sin(beta) on y, 3 kN·m on z plus a cubic
// in time) under 2 kN·m white noise: held out, SINDy comes within 5 % of the noise.
TEST(SindyBaseline, RecoversASparseResidualItsLibraryExpressesToTheNoise) {
  const std::vector<MeasurementSample> inputs = recording_inputs(LoadSequenceKind::moment_sweep);
  const auto truth = [](const MeasurementSample& s) {
    const double t = s.time_s / 192.0;
    return SensorMoments{5000.0 * s.torque_nm / 1.5e6 * std::sin(s.direction_rad), 3000.0 + 4000.0 * t * t * t};
  };
  const ChannelNoise train_noise = white_noise(inputs.size(), 2000.0, 1), test_noise = white_noise(inputs.size(), 2000.0, 2);
  std::vector<SensorMoments> train(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    train[i] = {truth(inputs[i]).y_nm + train_noise[i].y_nm, truth(inputs[i]).z_nm + train_noise[i].z_nm};
  }
  const SindyModel model = fit_sindy(inputs, train);
  const std::vector<SensorMoments> fitted = predict_sindy(model, inputs);
  double sum = 0.0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const double ry = truth(inputs[i]).y_nm + test_noise[i].y_nm - fitted[i].y_nm;
    const double rz = truth(inputs[i]).z_nm + test_noise[i].z_nm - fitted[i].z_nm;
    sum += ry * ry + rz * rz;
  }
  EXPECT_LT(std::sqrt(sum / (2.0 * inputs.size())), 1.05 * 2000.0)
      << "y: " << model.y.active_terms << " terms at " << model.y.threshold_nm << " N·m, cv " << model.y.cv_rmse_nm
      << "; z: " << model.z.active_terms << " terms at " << model.z.threshold_nm << " N·m, cv " << model.z.cv_rmse_nm;
  EXPECT_LT(model.y.active_terms, 20) << "the one-standard-error rule keeps the fit sparse";
}

}  // namespace
}  // namespace gc::independent
