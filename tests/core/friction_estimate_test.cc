#include "core/friction_estimate.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>

#include "core/coupling_geometry.h"
#include "core/induced_moments.h"
#include "core/model_error.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::deg;
using testing::nrel_upwind;

const CouplingGeometry& upwind() { return testing::upwind_geometry(); }

FrictionMeasurement measure(const OperatingPoint& point) {
  const InducedMoments m = induced_moments(upwind(), point);
  return {point.torque_nm, point.misalignment_rad, point.direction_rad, m.sensor_moment_y_nm,
          m.sensor_moment_z_nm};
}

TEST(FrictionEstimate, Eq3UndoesEqs44To48Exactly) {
  const OperatingPoint point{1.2e6, deg(0.45), deg(130), 0.11};
  const InducedMoments m = induced_moments(upwind(), point);
  const FrictionEstimate e = estimate_friction(upwind(), measure(point));
  EXPECT_NEAR(e.moment_z_dd_nm, m.moment_z_dd_nm, 1e-9 * std::abs(m.moment_z_dd_nm));
  EXPECT_NEAR(e.friction_coefficient, m.moment_z_dd_nm / 1.2e6 - std::tan(deg(0.45)), 1e-15);
}

TEST(FrictionEstimate, Eq4RecoversTheFrictionUsedWithinItsApproximation) {
  // Eq 4 puts every tooth load on the z'' axis; eq 42 spreads it over the loaded arc, weighted
  // by cos(theta_j). So eq 4 underestimates mu: by about a third when every tooth carries load
  // (mean |cos| about 2/pi, times 1/cos phi) and by a few % near the jam angle, where the few
  // loaded teeth sit near z''. Measured over 10-90 % of the jam angle, 0.3-2.2 MN·m,
  // mu = 0.05-0.15: relative error -33 % to -3 %; absolute error at most 0.049, and at most
  // 0.029 from 60 % of the jam angle.
  const double jam = upwind().jam_angle().angle_rad;
  for (double mu : {0.05, 0.10, 0.15}) {
    for (double fraction : {0.1, 0.3, 0.6, 0.9}) {
      for (double torque : {0.3e6, 1.0e6, 2.2e6}) {
        for (double beta : {0.0, deg(45.0), deg(250.0)}) {
          const OperatingPoint point{torque, fraction * jam, beta, mu};
          const double estimate = estimate_friction(upwind(), measure(point)).friction_coefficient;
          const double relative = (estimate - mu) / mu;
          EXPECT_LT(relative, 0.0) << mu << " " << fraction << " " << torque;
          EXPECT_GT(relative, -0.35) << mu << " " << fraction << " " << torque;
          EXPECT_LT(mu - estimate, fraction >= 0.6 ? 0.03 : 0.05) << mu << " " << fraction;
        }
      }
    }
  }
}

TEST(FrictionEstimate, SignFollowsEq37NotThePrintedEq2) {
  // As printed, eq 4 returns a negative mu on the model's own moments; as read it is positive.
  const double jam = upwind().jam_angle().angle_rad;
  const double estimate =
      estimate_friction(upwind(), measure({1.5e6, 0.6 * jam, 0.0, 0.12})).friction_coefficient;
  EXPECT_GT(estimate, 0.05);
}

TEST(FrictionEstimate, RejectsBadMeasurementsNamingTheField) {
  FrictionMeasurement m{1e6, deg(0.3), 0.0, 1e5, 1e5};
  m.sensor_moment_z_nm = std::nan("");
  try {
    estimate_friction(upwind(), m);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "measurement.sensor_moment_z_nm");
  }
  m.sensor_moment_z_nm = 0.0;
  m.torque_nm = 0.0;
  EXPECT_THROW(estimate_friction(upwind(), m), InvalidInput);
}

/// The InvalidInput `measurement` raises.
InvalidInput rejection(const FrictionMeasurement& measurement) {
  try {
    const FrictionEstimate e = estimate_friction(upwind(), measurement);
    ADD_FAILURE() << "accepted, mu = " << e.friction_coefficient;
  } catch (const InvalidInput& e) {
    return e;
  }
  return InvalidInput("(accepted)", "");
}

/// The bounds of "allowed [a, b]" in an InvalidInput's message.
std::pair<double, double> allowed_range(const std::string& message) {
  const std::size_t at = message.find("allowed [");
  double a = 0.0;
  double b = 0.0;
  EXPECT_NE(at, std::string::npos) << message;
  EXPECT_EQ(std::sscanf(message.c_str() + at, "allowed [%lf, %lf]", &a, &b), 2) << message;
  return {a, b};
}

TEST(FrictionEstimate, MisalignmentBeyondTheJamAngleIsRejected) {
  // Issue 9: a misalignment of 1 rad gave mu = -1.51 with STATUS_OK.
  const InvalidInput e = rejection({1e6, 1.0, 0.0, 1e5, 1e5});
  EXPECT_EQ(e.field(), "measurement.misalignment_rad");
  EXPECT_NE(std::string(e.what()).find("jam angle"), std::string::npos) << e.what();
  EXPECT_EQ(rejection({1e6, upwind().jam_angle().angle_rad, 0.0, 1e5, 1e5}).field(),
            "measurement.misalignment_rad");
}

TEST(FrictionEstimate, AnEstimateOutsideZeroToOneIsAnErrorNamingTheMomentAndItsRange) {
  // Issue 9: a moment of 1e308 gave mu = 2.28e301 with STATUS_OK.
  const OperatingPoint point{1.5e6, 0.6 * upwind().jam_angle().angle_rad, 0.0, 0.12};
  const FrictionMeasurement valid = measure(point);
  for (const double huge : {1e308, -1e308, 1e12}) {
    FrictionMeasurement m = valid;
    m.sensor_moment_z_nm = huge;  // dominates M_tz'' at beta = 0
    const InvalidInput e = rejection(m);
    EXPECT_EQ(e.field(), "measurement.sensor_moment_z_nm") << huge;
    EXPECT_NE(std::string(e.what()).find("mu = "), std::string::npos) << e.what();
    // The range stated is the right one: its ends give mu = 0 and 1 (eq 4 is linear in it).
    const auto [lo, hi] = allowed_range(e.what());
    ASSERT_LT(lo, hi);
    for (const double inside : {lo + 1e-3 * (hi - lo), 0.5 * (lo + hi), hi - 1e-3 * (hi - lo)}) {
      m.sensor_moment_z_nm = inside;
      const double mu = estimate_friction(upwind(), m).friction_coefficient;
      EXPECT_GE(mu, 0.0);
      EXPECT_LE(mu, 1.0);
    }
    m.sensor_moment_z_nm = 0.5 * (lo + hi);
    EXPECT_NEAR(estimate_friction(upwind(), m).friction_coefficient, 0.5, 1e-6);
  }
}

TEST(FrictionEstimate, ANegativeEstimateIsAnErrorNamingTheDominantMoment) {
  // No moment at all at a misalignment: eq 4 gives mu = -tan(zeta).
  const double zeta = 0.5 * upwind().jam_angle().angle_rad;
  FrictionMeasurement m{1e6, zeta, deg(90) - upwind().pressure_angle_rad(), 0.0, 0.0};
  m.sensor_moment_y_nm = -self_weight_moment_nm(upwind());  // the coupling's moment is zero
  // psi = 90 deg: M_tz'' comes from the y moment alone, so it is the one named.
  const InvalidInput e = rejection(m);
  EXPECT_EQ(e.field(), "measurement.sensor_moment_y_nm");
  EXPECT_NE(std::string(e.what()).find("mu = -"), std::string::npos) << e.what();
  const auto [lo, hi] = allowed_range(e.what());
  m.sensor_moment_y_nm = 0.5 * (lo + hi);
  EXPECT_NEAR(estimate_friction(upwind(), m).friction_coefficient, 0.5, 1e-6);
}

TEST(FrictionEstimate, EstimatesOfTheModelsOwnMomentsStayValid) {
  // What tests/service/remote_equals_in_process_test.cc sends: every one lies in [0, 1].
  const double jam = upwind().jam_angle().angle_rad;
  for (double torque : {2.0e5, 1.5e6, 3.4e6}) {
    for (double fraction : {0.3, 0.9}) {
      const double mu =
          estimate_friction(upwind(), measure({torque, fraction * jam, 0.4, 0.12}))
              .friction_coefficient;
      EXPECT_GE(mu, 0.0);
      EXPECT_LE(mu, 1.0);
    }
  }
}

}  // namespace
}  // namespace gc
