// The identity oracle (identity_oracle.h) against what is known: a truth that IS a member of a rival
// family is not told apart from it (d near 0), for a linear family and for a physical one with the
// model's int(qN/4) steps; a shape outside a linear family stands at the distance least squares
// gives by hand, on all rows and thinned and scaled; the rivals a truth is judged against; and a
// draw gives the same identity d twice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "tests/diagnosis/zoo/couplings.h"
#include "tests/diagnosis/zoo/identity_oracle.h"
#include "tests/diagnosis/zoo/oracle.h"
#include "tests/diagnosis/zoo/zoo.h"

namespace gc::zoo {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<double> white(std::size_t n, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> e(0.0, sigma);
  std::vector<double> x(n);
  for (auto& v : x) v = e(rng);
  return x;
}

// a + b t/n on M_sy' (a and b free), nothing on M_sz'.
SignalFamily line_family(std::size_t n) {
  SignalFamily f;
  f.name = "line";
  f.parameters = {{"a", -kInf, kInf, 1.0}, {"b", -kInf, kInf, 1.0}};
  f.none = {0.0, 0.0};
  f.signal = [n](const std::vector<double>& th, std::vector<double>& y, std::vector<double>& z) {
    y.resize(n), z.assign(n, 0.0);
    for (std::size_t t = 0; t < n; ++t) y[t] = th[0] + th[1] * static_cast<double>(t) / static_cast<double>(n);
  };
  return f;
}

// The least-squares residual of s against span{1, t/n}, by the 2x2 normal equations: |P_perp s|^2.
double residual_off_a_line(const std::vector<double>& s) {
  const double n = static_cast<double>(s.size());
  double st = 0, stt = 0, sy = 0, sty = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double t = static_cast<double>(i) / n;
    st += t, stt += t * t, sy += s[i], sty += t * s[i];
  }
  const double det = n * stt - st * st;
  const double a = (stt * sy - st * sty) / det, b = (n * sty - st * sy) / det;
  double r2 = 0;
  for (std::size_t i = 0; i < s.size(); ++i) r2 += std::pow(s[i] - a - b * static_cast<double>(i) / n, 2);
  return r2;
}

TEST(ZooIdentity, AMemberOfALinearRivalIsNotToldApart) {
  const std::size_t n = 3000;
  std::vector<double> sy(n), sz(n, 0.0);
  for (std::size_t t = 0; t < n; ++t) sy[t] = 0.4 - 0.9 * static_cast<double>(t) / n;
  const IdentityBound b = identity_bound(sy, sz, white(n, 1.0, 1), white(n, 1.0, 2), kNaN, {line_family(n)});
  EXPECT_GT(b.detection_thinned_d, 8.0);   // clearly detected: about sqrt(n (0.4^2 - 0.4 0.9 + 0.27)) = 13
  EXPECT_LT(b.d, 1e-3);                    // ...and exactly a line
  EXPECT_EQ(b.rival, "line");
}

TEST(ZooIdentity, AShapeOffALineStandsAtTheLeastSquaresDistance) {
  // White noise sigma 1: d^2 = |P_perp s|^2 / sigma^2 with s a ramp plus a slow ripple.
  const std::size_t n = 4000;
  std::vector<double> sy(n), sz(n, 0.0);
  for (std::size_t t = 0; t < n; ++t) sy[t] = 0.3 * t / double(n) + 0.12 * std::sin(2 * std::numbers::pi * t / 500.0);
  const double expected = std::sqrt(residual_off_a_line(sy));   // about 0.12 sqrt(n / 2) = 5.4
  const IdentityBound b = identity_bound(sy, sz, white(n, 1.0, 3), white(n, 1.0, 4), kNaN, {line_family(n)});
  EXPECT_NEAR(b.d, expected, 0.05 * expected);
  EXPECT_LT(b.d, b.detection_thinned_d);
  EXPECT_NEAR(b.power, 0.5 * std::erfc(-(b.d - 2.3263478740408408) / std::sqrt(2.0)), 1e-12);
}

TEST(ZooIdentity, ThinnedRowsScaledByTheDetectionRatioGiveTheFullRecordsDistance) {
  // 20,000 rows read as every 10th (2,000), the distance scaled by the detection d on all rows.
  const std::size_t n = 20000;
  std::vector<double> sy(n), sz(n, 0.0);
  for (std::size_t t = 0; t < n; ++t) sy[t] = 0.05 * t / double(n) + 0.05 * std::sin(2 * std::numbers::pi * t / 3000.0);
  const std::vector<double> ny = white(n, 1.0, 5), nz = white(n, 1.0, 6);
  const double expected = std::sqrt(residual_off_a_line(sy));   // about 0.05 sqrt(n / 2) = 5.0
  const double full = oracle_bound(sy, sz, ny, nz).d;
  const std::vector<std::size_t> rows = thinned_rows(n, 2000);
  ASSERT_EQ(rows.size(), 2000u);
  EXPECT_EQ(rows[1], 10u);
  std::vector<double> ty, tz, my, mz;
  for (std::size_t i : rows) ty.push_back(sy[i]), tz.push_back(sz[i]), my.push_back(ny[i]), mz.push_back(nz[i]);
  SignalFamily line = line_family(rows.size());
  line.signal = [&rows, n](const std::vector<double>& th, std::vector<double>& y, std::vector<double>& z) {
    y.resize(rows.size()), z.assign(rows.size(), 0.0);
    for (std::size_t k = 0; k < rows.size(); ++k) y[k] = th[0] + th[1] * static_cast<double>(rows[k]) / static_cast<double>(n);
  };
  const IdentityBound b = identity_bound(ty, tz, my, mz, full, {line});
  EXPECT_NEAR(b.scale, std::sqrt(10.0), 0.1 * std::sqrt(10.0));   // white noise: sqrt(k)
  EXPECT_NEAR(b.d, expected, 0.1 * expected);
}

TEST(ZooIdentity, TheRivalsLeaveOutTheNamesThatCountAndTheZooLabelsOfTheSamePhysics) {
  const auto has = [](const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); };
  const auto assembly = identity_rivals("assembly_misalignment");
  EXPECT_FALSE(has(assembly, "assembly_misalignment"));
  EXPECT_FALSE(has(assembly, "misalignment_offset"));   // its "misalignment" counts assembly_misalignment
  EXPECT_TRUE(has(assembly, "eccentricity"));
  EXPECT_TRUE(has(assembly, "thermal_misalignment"));
  const auto gain = identity_rivals("torque_gain");
  EXPECT_FALSE(has(gain, "torque_calibration"));        // "torque" counts it
  EXPECT_TRUE(has(gain, "compliance"));
  const auto weight = identity_rivals("self_weight");
  EXPECT_FALSE(has(weight, "weight"));
  EXPECT_FALSE(has(weight, "channel_gain_offset"));
  EXPECT_EQ(identity_rivals("compliance").size(), hidden_effect_table().size() - 1);
}

TEST(ZooIdentity, AnOffsetWithinTheAssemblyRangeIsAnAssemblyMisalignment) {
  // A physical family with the model's int(qN/4) steps: the truth is misalignment_offset's member
  // at an offset the assembly misalignment reaches too; the fit must find it (d near 0 against a
  // detection d of hundreds: the steps crossed by one side only make the distance a narrow cusp).
  DrawLimits lim;
  lim.min_rows = lim.max_rows = 2500;
  lim.only_families = {"white"};
  lim.keep_channels = true;
  const ZooDraw d = draw(14, lim);
  const auto model = load_choice(d.model);
  const double jam = model->geometry().jam_angle().angle_rad;
  const Channels& clean = d.truth;
  const double zeta0 = 0.1 * std::min(0.05, 0.35 * jam), beta0 = 0.7;
  const HiddenEffectFamily offset = hidden_effect_family("misalignment_offset", *model, jam, clean);
  const std::size_t n = clean.rows();
  std::vector<std::size_t> rows(n);
  std::vector<double> sy(n), sz(n), ny(n), nz(n);
  for (std::size_t i = 0; i < n; ++i) {
    rows[i] = i;
    const SensorMoments m = offset.moments({zeta0, beta0, 1.0}, i);
    sy[i] = m.y_nm - clean.msy_nm[i], sz[i] = m.z_nm - clean.msz_nm[i];
    ny[i] = d.logged.msy_nm[i] - clean.msy_nm[i], nz[i] = d.logged.msz_nm[i] - clean.msz_nm[i];
  }
  const IdentityBound b = identity_bound(sy, sz, ny, nz, kNaN, {signal_family("assembly_misalignment", *model, jam, clean, rows)});
  EXPECT_GT(b.detection_thinned_d, 100.0) << d.description;   // 414
  EXPECT_LT(b.d, 1.0) << d.description;                       // 1e-7 on the machine it was written on
}

TEST(ZooIdentity, ADrawGivesTheSameIdentityTwice) {
  DrawLimits lim;
  lim.min_rows = 3000;
  lim.max_rows = 6000;
  lim.effect_truth = "eccentricity";
  lim.effect_snr = 1.5;
  const ZooDraw a = draw(20261310, lim), b = draw(20261310, lim);
  ASSERT_TRUE(std::isfinite(a.identity_d)) << a.description;
  EXPECT_EQ(a.identity_d, b.identity_d);
  EXPECT_EQ(a.identity_rival, b.identity_rival);
  EXPECT_FALSE(a.identity_rival.empty());
  EXPECT_LE(a.identity_d, a.oracle_d * (1 + 1e-9));   // the no-effect member is in every family
  EXPECT_NEAR(a.identity_power, 0.5 * std::erfc(-(a.identity_d - 2.3263) / std::sqrt(2.0)), 1e-4);
  lim.effect_truth.clear();
  const ZooDraw none = draw(20261310, lim);
  EXPECT_TRUE(std::isnan(none.identity_d));
  EXPECT_TRUE(none.identity_rival.empty());
}

}  // namespace
}  // namespace gc::zoo
