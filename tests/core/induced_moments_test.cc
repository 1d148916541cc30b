#include "core/induced_moments.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/QR>

#include "core/coupling_geometry.h"
#include "core/model_error.h"
#include "core/tooth_load_pattern.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::deg;
using testing::nrel_upwind;

const CouplingGeometry& upwind() { return testing::upwind_geometry(); }

// Coefficient of determination of the least-squares line through (x, y).
double r_squared(const std::vector<double>& x, const std::vector<double>& y) {
  const Eigen::Map<const Eigen::VectorXd> xs(x.data(), static_cast<Eigen::Index>(x.size()));
  const Eigen::Map<const Eigen::VectorXd> ys(y.data(), static_cast<Eigen::Index>(y.size()));
  Eigen::MatrixXd design(xs.size(), 2);
  design << Eigen::VectorXd::Ones(xs.size()), xs;
  const Eigen::VectorXd fit = design.colPivHouseholderQr().solve(ys);
  const double residual = (ys - design * fit).squaredNorm();
  return 1.0 - residual / (ys.array() - ys.mean()).square().sum();
}

std::vector<double> magnitudes_over_misalignment(double mu, std::vector<double>& angles) {
  const double jam = upwind().jam_angle().angle_rad;
  std::vector<double> m;
  for (int k = 1; k < 40; ++k) {
    angles.push_back(jam * k / 40.0);
    m.push_back(induced_moments(upwind(), {1.5e6, angles.back(), 0.0, mu}).magnitude_nm);
  }
  return m;
}

TEST(InducedMoments, GrowLinearlyWithMisalignmentAtFixedTorque) {
  // In an independent Python prototype the printed eq 13 (residue in radians) gives R^2 = 0.92
  // without friction and 0.40 with
  // mu = 0.12 on this grid; the residue read as a fraction of a tooth pitch: 0.998 and 0.98.
  std::vector<double> angles;
  const std::vector<double> frictionless = magnitudes_over_misalignment(0.0, angles);
  EXPECT_GT(r_squared(angles, frictionless), 0.99);
  angles.clear();
  const std::vector<double> with_friction = magnitudes_over_misalignment(0.12, angles);
  EXPECT_GT(r_squared(angles, with_friction), 0.97);
  // The quarter sums of eqs 42-43 end at int(qN/4) and alpha (eq 13) wraps with the residue
  // of qN: the moment is a sawtooth around its trend. Largest step down measured on this grid
  // 5.9 %, on a 200-point grid 7.8 % (docs/model.md).
  for (std::size_t i = 1; i < with_friction.size(); ++i) {
    EXPECT_GT(with_friction[i], 0.92 * with_friction[i - 1]) << "step at " << i;
  }
}

TEST(InducedMoments, GrowLinearlyWithTorqueAtFixedMisalignment) {
  const double zeta = 0.6 * upwind().jam_angle().angle_rad;
  std::vector<double> torques, moments;
  for (int k = 2; k <= 20; ++k) {
    torques.push_back(1e5 * k);
    moments.push_back(induced_moments(upwind(), {torques.back(), zeta, 0.0, 0.12}).magnitude_nm);
  }
  EXPECT_GT(r_squared(torques, moments), 0.995);  // printed eq 13: 0.92
  EXPECT_GT(moments.back(), 8.0 * moments.front());
}

TEST(InducedMoments, AtSixtyPercentOfJamWithPaperFrictionReachTenToFifteenPercent) {
  // Section 6.3: up to 14 % of the 1.5 MN·m reference torque, with mu about 0.1-0.15.
  const double zeta = 0.6 * upwind().jam_angle().angle_rad;
  const double low = induced_moments(upwind(), {1.5e6, zeta, 0.0, 0.10}).magnitude_nm / 1.5e6;
  const double high = induced_moments(upwind(), {1.5e6, zeta, 0.0, 0.15}).magnitude_nm / 1.5e6;
  EXPECT_GT(low, 0.08);
  EXPECT_LT(high, 0.16);
  EXPECT_GT(high, low);
}

TEST(InducedMoments, WithoutFrictionTheyStayAtAFewPercent) {
  const double zeta = 0.6 * upwind().jam_angle().angle_rad;
  const double ratio = induced_moments(upwind(), {1.5e6, zeta, 0.0, 0.0}).magnitude_nm / 1.5e6;
  EXPECT_GT(ratio, 0.01);
  EXPECT_LT(ratio, 0.05);
}

TEST(InducedMoments, DirectionIsShiftedFromTheMisalignmentAxisByThePressureAngle) {
  // Eqs 44-45: the coupling-frame moment is the double-prime moment rotated by phi + beta.
  for (double beta_deg : {0.0, 35.0, 200.0}) {
    const InducedMoments m = induced_moments(upwind(), {1.5e6, deg(0.4), deg(beta_deg), 0.1});
    const double in_double_prime = std::atan2(m.moment_z_dd_nm, m.moment_y_dd_nm);
    const double shift = std::remainder(in_double_prime - m.direction_rad, 2 * M_PI);
    EXPECT_NEAR(shift, std::remainder(deg(20.0 + beta_deg), 2 * M_PI), 1e-12) << beta_deg;
    EXPECT_NEAR(m.magnitude_nm, std::hypot(m.moment_y_dd_nm, m.moment_z_dd_nm), 1e-6);
  }
}

TEST(InducedMoments, TurningTheMisalignmentTurnsTheMomentOnly) {
  const InducedMoments a = induced_moments(upwind(), {1.5e6, deg(0.4), 0.0, 0.1});
  const InducedMoments b = induced_moments(upwind(), {1.5e6, deg(0.4), deg(90), 0.1});
  EXPECT_NEAR(a.magnitude_nm, b.magnitude_nm, 1e-6);
  EXPECT_NEAR(std::remainder(a.direction_rad - b.direction_rad, 2 * M_PI), deg(90), 1e-12);
}

TEST(InducedMoments, SensorMomentsCarryTheSelfWeightInYOnlyEq48) {
  // W_c L_s + w_sh L_s^2 / 2 = 24 kN * 2.8 m + 21.1 kN/m * 2.8^2 / 2 m^2 = 149.912 kN·m.
  const InducedMoments m = induced_moments(upwind(), {1.5e6, deg(0.3), deg(10), 0.1});
  EXPECT_NEAR(m.self_weight_moment_nm, 149912.0, 1e-6);
  EXPECT_DOUBLE_EQ(m.sensor_moment_y_nm, m.moment_y_nm - 149912.0);
  EXPECT_DOUBLE_EQ(m.sensor_moment_z_nm, m.moment_z_nm);
}

TEST(InducedMoments, AxialToothLoadEq37) {
  EXPECT_NEAR(axial_tooth_load_n(1000.0, deg(1.0), 0.0), 1000.0 * std::tan(deg(1.0)), 1e-9);
  const double c = std::cos(deg(1.0));
  const double s = std::sin(deg(1.0));
  EXPECT_NEAR(axial_tooth_load_n(1000.0, deg(1.0), 0.1), 1000.0 * (0.1 * c + s) / (c - 0.1 * s),
              1e-9);
}

TEST(InducedMoments, SumsRunOverTheSymmetricQuarter) {
  const ToothContact contact = tooth_contact(upwind(), {1.5e6, deg(0.5), 0.0, 0.0});
  const InducedMoments m = induced_moments(upwind(), {1.5e6, deg(0.5), 0.0, 0.0}, contact);
  EXPECT_EQ(m.teeth_summed, 4 * (static_cast<int>(contact.load_sharing.q * 100 / 4) + 1));
}

TEST(InducedMoments, AlignedAndFrictionlessGivesNoMoment) {
  const InducedMoments m = induced_moments(upwind(), {1.5e6, 0.0, 0.0, 0.0});
  EXPECT_EQ(m.moment_y_dd_nm, 0.0);
  EXPECT_EQ(m.moment_z_dd_nm, 0.0);
}

// The model's prediction takes the moments without the tooth table: the same numbers bit for bit,
// and the same refusal, over torque, misalignment, friction and both forms of the quarter sums.
TEST(InducedMoments, DoublePrimeMomentsAloneAreThoseOfTheFullContactBitForBit) {
  const double jam = upwind().jam_angle().angle_rad;
  int compared = 0, refused = 0;
  for (const bool continuous : {false, true}) {
    ContactOptions options;
    options.continuous_quarter_sums = continuous;
    for (int t = 1; t <= 23; ++t) {
      for (int z = 0; z <= 19; ++z) {
        const OperatingPoint point{5e3 * t * t, jam * z / 20.0, 0.1 * t, 0.005 * (t % 5)};
        try {
          const InducedMoments full = induced_moments(upwind(), point, tooth_contact(upwind(), point, options));
          const QuarterSums alone = double_prime_moments(upwind(), point, options);
          EXPECT_EQ(alone.moment_y_dd_nm, full.moment_y_dd_nm);
          EXPECT_EQ(alone.moment_z_dd_nm, full.moment_z_dd_nm);
          EXPECT_EQ(alone.teeth_summed, full.teeth_summed);
          ++compared;
        } catch (const InvalidInput&) {
          EXPECT_THROW(double_prime_moments(upwind(), point, options), InvalidInput);
          ++refused;
        }
      }
    }
  }
  EXPECT_GT(compared, 700);
  EXPECT_GT(refused, 0);  // light torque near the jam angle
}

/// Eq 9 tooth by tooth, written here apart from the core: P_d = P_i max(0, 1 - r sin^2 theta_j).
ToothLoadTotals totals_tooth_by_tooth(const CouplingGeometry& coupling, const ToothLoadPattern& p) {
  ToothLoadTotals t;
  for (int j = 0; j < coupling.teeth(); ++j) {
    const double s = coupling.tooth_sin()[j] * p.cos_alpha + coupling.tooth_cos()[j] * p.sin_alpha;
    const double share = 1.0 - p.separation_ratio * s * s;
    const double load = p.peak_tooth_load_n * (share > 0.0 ? share : 0.0);
    t.loaded_teeth += load > 0.0;
    t.sum_of_loads_n += load;
    if (load > t.max_load_n) {
      t.max_load_n = load;
      t.max_load_tooth = j;
    }
  }
  return t;
}

// The totals without a pass over the teeth (two runs of loaded teeth about theta = 0 and pi) are
// the pass's: the count, the most loaded tooth and its load bit for bit, the sum within 1e-12 of
// P_t. Over torque and misalignment up to the jam angle (from every tooth loaded to a few), on an
// even and an odd tooth count, with the paper's and the continuous quarter sums (another alpha),
// and with a spacing error; and where the refusal of light loads falls, it falls alike.
TEST(InducedMoments, ToothTotalsWithoutAPassOverTheTeethAreThePass) {
  CouplingDefinition odd_definition = nrel_upwind();
  odd_definition.teeth = 101;
  odd_definition.module_m = odd_definition.pitch_diameter_m / 101;
  const CouplingGeometry odd(odd_definition);
  for (const CouplingGeometry* coupling : {&upwind(), &odd}) {
    const double jam = coupling->jam_angle().angle_rad;
    int compared = 0, few = 0, all = 0;
    for (const bool continuous : {false, true}) {
      ContactOptions options;
      options.min_load_fraction = 0.0;
      options.continuous_quarter_sums = continuous;
      options.spacing_error_m = continuous ? 20e-6 : 0.0;
      for (int t = 1; t <= 40; ++t) {
        for (int z = 0; z <= 79; ++z) {
          const OperatingPoint point{2e3 * t * t, jam * z / 80.0, 0.1 * t, 0.1};
          const ToothLoadPattern pattern = tooth_load_pattern(*coupling, point, options);
          const ToothLoadTotals fast = tooth_load_totals(*coupling, pattern);
          const ToothLoadTotals pass = totals_tooth_by_tooth(*coupling, pattern);
          const std::string at = std::to_string(coupling->teeth()) + " teeth, T " + std::to_string(point.torque_nm) +
                                 " N·m, zeta " + std::to_string(point.misalignment_rad);
          EXPECT_EQ(fast.loaded_teeth, pass.loaded_teeth) << at;
          EXPECT_EQ(fast.max_load_tooth, pass.max_load_tooth) << at;
          EXPECT_EQ(fast.max_load_n, pass.max_load_n) << at;
          EXPECT_NEAR(fast.sum_of_loads_n, pass.sum_of_loads_n, 1e-12 * pattern.total_normal_load_n) << at;
          ++compared;
          few += pass.loaded_teeth <= 10;
          all += pass.loaded_teeth == coupling->teeth();
        }
      }
    }
    EXPECT_EQ(compared, 6400);
    EXPECT_GT(few, 50) << coupling->teeth() << " teeth";  // light torque near the jam angle
    EXPECT_GT(all, 50) << coupling->teeth() << " teeth";  // no misalignment
  }
}

// The same on patterns made by hand, where rounding is hardest: alpha at and beside pi / N (a tooth
// then lies at 90 deg on a tooth count of 4k + 2), z_o / z_e about 1 (every tooth loaded, the ones
// at 90 deg barely) and large (a few teeth), on 100 to 103 teeth.
TEST(InducedMoments, ToothTotalsWithoutAPassHoldAtTheEdgesOfRounding) {
  int compared = 0;
  for (const int teeth : {100, 101, 102, 103}) {
    CouplingDefinition definition = nrel_upwind();
    definition.teeth = teeth;
    definition.module_m = definition.pitch_diameter_m / teeth;
    const CouplingGeometry coupling(definition);
    for (const double alpha_in_half_pitches : {1.0, std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0), 1.1, 1.25}) {
      for (const double r : {0.0, 0.5, 1.0 - 1e-12, 1.0, 1.0 + 1e-12, 2.0, 50.0, 1e6}) {
        ToothLoadPattern p;
        p.offset_alpha_rad = alpha_in_half_pitches * M_PI / teeth;
        p.sin_alpha = std::sin(p.offset_alpha_rad);
        p.cos_alpha = std::cos(p.offset_alpha_rad);
        p.separation_ratio = r;
        p.peak_tooth_load_n = 1e4;
        p.total_normal_load_n = 1e4 * teeth;
        const ToothLoadTotals fast = tooth_load_totals(coupling, p);
        const ToothLoadTotals pass = totals_tooth_by_tooth(coupling, p);
        const std::string at = std::to_string(teeth) + " teeth, alpha " + std::to_string(alpha_in_half_pitches) +
                               " half pitches, r " + std::to_string(r);
        EXPECT_EQ(fast.loaded_teeth, pass.loaded_teeth) << at;
        EXPECT_EQ(fast.max_load_tooth, pass.max_load_tooth) << at;
        EXPECT_EQ(fast.max_load_n, pass.max_load_n) << at;
        EXPECT_NEAR(fast.sum_of_loads_n, pass.sum_of_loads_n, 1e-12 * p.total_normal_load_n) << at;
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 160);
}

}  // namespace
}  // namespace gc
