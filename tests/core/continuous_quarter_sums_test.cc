// Issue 8: the continuous variant of eqs 13 and 42-43 (ContactOptions::continuous_quarter_sums,
// docs/model.md). It must equal the paper's form where qN/4 is a whole number and have none of
// its sawtooth steps in between.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/coupling_geometry.h"
#include "core/induced_moments.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

const CouplingGeometry& upwind() { return testing::upwind_geometry(); }

ContactOptions options_with(bool continuous) {
  ContactOptions options;
  options.continuous_quarter_sums = continuous;
  return options;
}

double magnitude(const OperatingPoint& point, bool continuous) {
  return induced_moments(upwind(), point, options_with(continuous)).magnitude_nm;
}

int whole_quarter(const OperatingPoint& point) {
  const double q = tooth_contact(upwind(), point).load_sharing.q;
  return static_cast<int>(q * upwind().teeth() / 4.0);
}

// Largest |M[i-1] - 2 M[i] + M[i+1]| / M[i] over a sweep: a step of s % between neighbours
// shows as about s %, while a smooth curve on a fine grid gives almost nothing.
double largest_kink(const std::vector<double>& m) {
  double largest = 0.0;
  for (std::size_t i = 1; i + 1 < m.size(); ++i) {
    largest = std::max(largest, std::abs(m[i - 1] - 2.0 * m[i] + m[i + 1]) / m[i]);
  }
  return largest;
}

TEST(ContinuousQuarterSums, AreOffByDefault) {
  EXPECT_FALSE(ContactOptions{}.continuous_quarter_sums);
  const OperatingPoint point{1.5e6, 0.6 * upwind().jam_angle().angle_rad, 0.0, 0.12};
  EXPECT_EQ(induced_moments(upwind(), point).magnitude_nm, magnitude(point, false));
}

TEST(ContinuousQuarterSums, EqualThePapersFormWhereAQuarterOfQNIsWhole) {
  // q grows with torque. Bisect the torque at which int(qN/4) steps up, at 60 % of the jam
  // angle with mu = 0.12, to 1e-9 of the bracket.
  const double zeta = 0.6 * upwind().jam_angle().angle_rad;
  double below = 4.0e5;
  double above = 8.0e5;
  const int first = whole_quarter({below, zeta, 0.0, 0.12});
  ASSERT_GT(whole_quarter({above, zeta, 0.0, 0.12}), first);
  for (int k = 0; k < 60 && above - below > 1e-9 * above; ++k) {
    const double middle = 0.5 * (below + above);
    (whole_quarter({middle, zeta, 0.0, 0.12}) > first ? above : below) = middle;
  }
  const OperatingPoint just_below{below, zeta, 0.0, 0.12};
  const OperatingPoint just_above{above, zeta, 0.0, 0.12};
  ASSERT_EQ(whole_quarter(just_above), first + 1);
  // Just above the whole number the two forms are one formula: equal to rounding.
  EXPECT_NEAR(magnitude(just_above, true) / magnitude(just_above, false), 1.0, 1e-6);
  // Just below it, the continuous form already has the paper's value from above, while the
  // paper's form is still a step away (measured: 8.7 % below, at 0.571 MN·m).
  EXPECT_NEAR(magnitude(just_below, true) / magnitude(just_above, false), 1.0, 1e-6);
  EXPECT_GT(std::abs(magnitude(just_below, false) / magnitude(just_above, false) - 1.0), 0.01);
}

// largest_kink of |M| along `point_at(x)`, x = 0 .. 1 in `count` points.
template <typename PointAt>
double sweep_kink(PointAt point_at, int count, bool continuous) {
  std::vector<double> m;
  for (int k = 0; k < count; ++k) m.push_back(magnitude(point_at(k / (count - 1.0)), continuous));
  return largest_kink(m);
}

// A step keeps its size as the grid refines; a corner (a change of slope) halves with each
// halving of the spacing. Measured on 400 / 1600 points, misalignment: paper 8.16 % / 8.18 %,
// continuous 1.06 % / 0.25 %; torque: paper 11.1 % / 11.0 %, continuous 1.28 % / 0.31 %.
TEST(ContinuousQuarterSums, HaveNoSawtoothOverMisalignment) {
  // 1.5 MN·m, mu = 0.12, from 5 % to 95 % of the jam angle.
  const double jam = upwind().jam_angle().angle_rad;
  const auto point_at = [jam](double x) {
    return OperatingPoint{1.5e6, jam * (0.05 + 0.9 * x), 0.0, 0.12};
  };
  const double paper_coarse = sweep_kink(point_at, 400, false);
  const double paper_fine = sweep_kink(point_at, 1600, false);
  EXPECT_GT(paper_fine, 0.07);
  EXPECT_GT(paper_fine, 0.9 * paper_coarse);  // steps: no smaller on the finer grid
  const double continuous_coarse = sweep_kink(point_at, 400, true);
  const double continuous_fine = sweep_kink(point_at, 1600, true);
  EXPECT_LT(continuous_fine, 0.004);
  EXPECT_GT(continuous_coarse, 3.5 * continuous_fine);  // corners only: about 4x smaller
}

TEST(ContinuousQuarterSums, HaveNoSawtoothOverTorque) {
  // 60 % of the jam angle, mu = 0.12, from 0.3 to 3.4 MN·m.
  const double zeta = 0.6 * upwind().jam_angle().angle_rad;
  const auto point_at = [zeta](double x) { return OperatingPoint{3.0e5 + 3.1e6 * x, zeta, 0.0, 0.12}; };
  const double paper_coarse = sweep_kink(point_at, 400, false);
  const double paper_fine = sweep_kink(point_at, 1600, false);
  EXPECT_GT(paper_fine, 0.10);
  EXPECT_GT(paper_fine, 0.9 * paper_coarse);
  const double continuous_coarse = sweep_kink(point_at, 400, true);
  const double continuous_fine = sweep_kink(point_at, 1600, true);
  EXPECT_LT(continuous_fine, 0.004);
  EXPECT_GT(continuous_coarse, 3.5 * continuous_fine);
}

TEST(ContinuousQuarterSums, CountTheEnteringToothInTheSums) {
  const OperatingPoint point{1.5e6, 0.5 * upwind().jam_angle().angle_rad, 0.0, 0.0};
  const ToothContact contact = tooth_contact(upwind(), point, options_with(true));
  const double quarter = contact.load_sharing.q * upwind().teeth() / 4.0;
  ASSERT_GT(quarter - std::floor(quarter), 0.0);
  EXPECT_EQ(induced_moments(upwind(), point, contact).teeth_summed,
            4 * (static_cast<int>(quarter) + 2));
}

}  // namespace
}  // namespace gc
