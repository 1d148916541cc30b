// Unit tests of the zoo's generator: seeds reproduce, each family gives the level it is asked for,
// input families leave the moments alone, export families do what they say, the draws stay within
// their limits, the Clopper-Pearson bound, and the artefacts' truths.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "tests/diagnosis/zoo/artefacts.h"
#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/harness.h"
#include "tests/diagnosis/zoo/zoo.h"

namespace gc::zoo {
namespace {

DrawLimits small(std::vector<std::string> families = {}) {
  DrawLimits l;
  l.min_rows = 3000;
  l.max_rows = 6000;
  l.only_families = std::move(families);
  l.keep_channels = true;
  return l;
}

TEST(ZooGenerator, SameSeedSameDrawOtherSeedOtherDraw) {
  const DrawLimits l = small();
  const ZooDraw a = draw(42, l), b = draw(42, l), c = draw(43, l);
  EXPECT_EQ(a.csv, b.csv);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.model.model_text, b.model.model_text);
  EXPECT_NE(a.csv, c.csv);
  EXPECT_NE(draw_seed(7, 0), draw_seed(7, 1));
  EXPECT_EQ(draw_seed(7, 3), draw_seed(7, 3));
}

TEST(ZooGenerator, EveryMomentFamilyGivesTheLevelAskedFor) {
  for (const Family& f : all_families()) {
    if (f.kind != FamilyKind::moment) continue;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const ZooDraw d = draw(seed, small({f.name}));
      Series ey(d.rows), ez(d.rows);
      for (std::size_t i = 0; i < d.rows; ++i) {
        ey[i] = d.logged.msy_nm[i] - d.truth.msy_nm[i];
        ez[i] = d.logged.msz_nm[i] - d.truth.msz_nm[i];
      }
      const double level = std::sqrt(0.5 * (std::pow(rms_about_mean(ey), 2) + std::pow(rms_about_mean(ez), 2)));
      if (std::string(f.name) == "spikes") {  // white at the level plus the spikes on top
        EXPECT_GE(level, 0.99 * d.level_nm) << f.name;
        EXPECT_LE(level, 4.0 * d.level_nm) << f.name << " " << d.description;
      } else {
        EXPECT_NEAR(level, d.level_nm, 0.02 * d.level_nm) << f.name << " " << d.description;
      }
      EXPECT_GE(d.level_share, 0.005);
      EXPECT_LE(d.level_share, 0.05);
      // The inputs are logged as they were.
      EXPECT_EQ(d.logged.torque_nm, d.truth.torque_nm) << f.name;
      EXPECT_EQ(d.logged.zeta_rad, d.truth.zeta_rad) << f.name;
    }
  }
}

TEST(ZooGenerator, TwoMomentFamiliesAddInQuadratureToTheLevel) {
  const ZooDraw d = draw(5, small({"ar1", "laplace"}));
  Series ey(d.rows);
  for (std::size_t i = 0; i < d.rows; ++i) ey[i] = d.logged.msy_nm[i] - d.truth.msy_nm[i];
  EXPECT_NEAR(rms_about_mean(ey), d.level_nm, 0.15 * d.level_nm) << d.description;  // cross terms of independent series
}

TEST(ZooGenerator, InputFamiliesNoiseTheInputsNotTheMoments) {
  for (const char* name : {"torque_sensor", "probes", "tachometer", "oil_rtd"}) {
    const ZooDraw d = draw(11, small({name}));  // plus "white" (a moment family is always there)
    ASSERT_EQ(d.families.size(), 2u) << name;
    const auto diff = [&](const std::vector<double>& a, const std::vector<double>& b) {
      double s = 0;
      for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
      return std::sqrt(s / a.size());
    };
    const std::string n = name;
    EXPECT_EQ(diff(d.logged.torque_nm, d.truth.torque_nm) > 0, n == "torque_sensor") << n;
    EXPECT_EQ(diff(d.logged.zeta_rad, d.truth.zeta_rad) > 0, n == "probes") << n;
    EXPECT_EQ(diff(d.logged.speed_rpm, d.truth.speed_rpm) > 0, n == "tachometer") << n;
    EXPECT_EQ(diff(d.logged.temperature_c, d.truth.temperature_c) > 0, n == "oil_rtd") << n;
    if (n == "torque_sensor") {
      EXPECT_LT(diff(d.logged.torque_nm, d.truth.torque_nm), 0.006 * 2.6e6 * d.model.torque_scale);
    }
    if (n == "probes") {
      for (double z : d.logged.zeta_rad) EXPECT_GT(z, 0.0);
    }
  }
}

TEST(ZooGenerator, ExportFamilies) {
  const ZooDraw q = draw(3, small({"white", "adc_step"}));
  // On the ADC's grid: the smallest difference of two distinct values is the step, >= 0.2 level.
  std::set<double> ys(q.logged.msy_nm.begin(), q.logged.msy_nm.end());
  double smallest = 1e300;
  for (auto it = std::next(ys.begin()); it != ys.end(); ++it) smallest = std::min(smallest, *it - *std::prev(it));
  EXPECT_GE(smallest, 0.19 * q.level_nm) << q.description;
  const ZooDraw j = draw(3, small({"white", "stamp_jitter"}));
  for (std::size_t i = 1; i < j.rows; ++i) ASSERT_GE(j.logged.time_s[i], j.logged.time_s[i - 1]);
  EXPECT_NE(j.logged.time_s, j.truth.time_s);
}

TEST(ZooGenerator, DrawsStayInTheirLimitsAndTheModelsRange) {
  DrawLimits l;
  l.min_rows = 1000;
  l.max_rows = 3000;
  l.keep_channels = true;
  std::set<std::string> models;
  for (std::uint64_t seed = 100; seed < 130; ++seed) {
    const ZooDraw d = draw(seed, l);
    EXPECT_GE(d.rows, 1000u);
    EXPECT_LE(d.rows, 3000u);
    EXPECT_GE(d.fs_hz, 0.99);
    EXPECT_LE(d.fs_hz, 1001.0);
    EXPECT_GE(d.families.size(), 1u);
    EXPECT_LE(d.families.size(), 4u);
    models.insert(d.model.description.substr(0, 6));
    for (std::size_t i = 0; i < d.rows; ++i) {
      ASSERT_GT(d.truth.torque_nm[i], 0.0) << d.description;
      ASSERT_GE(d.truth.speed_rpm[i], 2.999) << d.description;
      ASSERT_LE(d.truth.speed_rpm[i], 15.001) << d.description;
    }
    EXPECT_EQ(d.csv.substr(0, 5), "time_") << d.description;
  }
  EXPECT_GE(models.size(), 2u);  // bundled and scaled couplings both drawn
}

TEST(ZooGenerator, ClopperPearsonUpperBound) {
  EXPECT_NEAR(clopper_pearson_upper(0, 50), 1.0 - std::pow(0.025, 1.0 / 50), 1e-6);  // 0.0711
  EXPECT_NEAR(clopper_pearson_upper(5, 40), 0.2680, 2e-3);
  EXPECT_DOUBLE_EQ(clopper_pearson_upper(3, 3), 1.0);
}

TEST(ZooHarness, ReadsClaimsFromTheJson) {
  DiagnoseOutcome quiet;
  read_diagnosis_json(R"({"rounds":[{"outcome":"noise"}],"add_flags":[]})", quiet);
  EXPECT_FALSE(quiet.claim);
  EXPECT_FALSE(quiet.error);
  DiagnoseOutcome loud;
  read_diagnosis_json(R"({"rounds":[{"outcome":"effect_found","claimed":{"effect":"torque_calibration"},
     "ranking":[{"effect":"torque_calibration","held_out_rmse_nm":1000,"reduction":0.1,"t":5}]},{"outcome":"noise"}]})", loud);
  EXPECT_TRUE(loud.claim);
  ASSERT_FALSE(loud.claimed.empty());
  EXPECT_EQ(loud.claimed[0], "torque_calibration");
  DiagnoseOutcome unexplained;
  read_diagnosis_json(R"({"rounds":[{"outcome":"unexplained"}]})", unexplained);
  EXPECT_TRUE(unexplained.claim);
  DiagnoseOutcome flags;
  read_diagnosis_json(R"({"rounds":[{"outcome":"noise"}],"add_flags":["friction=mu0=0.2"]})", flags);
  EXPECT_TRUE(flags.claim);
}

TEST(ZooArtefacts, EveryKindReturnsTruthsInsideTheRecordAndChangesIt) {
  const ZooDraw d = draw(9, small({"white"}));
  for (const std::string& kind : artefact_kinds()) {
    for (std::uint64_t seed : {1u, 2u}) {
      const ArtefactRecording a = apply_artefact(d.logged, kind, seed);
      if (kind == "ringing" && a.truths.empty()) continue;  // a programme without a torque step
      ASSERT_FALSE(a.truths.empty()) << kind;
      for (const ArtefactTruth& t : a.truths) {
        EXPECT_EQ(t.kind, kind);
        EXPECT_EQ(t.rows, d.rows);
        EXPECT_LE(t.first_row, t.last_row);
        EXPECT_LT(t.last_row, d.rows);
      }
      const std::string before = write_csv(d.logged, {}), after = write_csv(a.rec, {}, a.empty);
      EXPECT_NE(before, after) << kind;
    }
  }
}

TEST(ZooArtefacts, SpikesAreIsolatedAndARunIsARun) {
  const ZooDraw d = draw(9, small({"white"}));
  const ArtefactRecording s = apply_artefact(d.logged, "spike", 4);
  std::set<std::size_t> rows;
  for (const auto& t : s.truths) {
    EXPECT_EQ(t.first_row, t.last_row);
    rows.insert(t.first_row);
  }
  for (std::size_t r : rows) EXPECT_FALSE(rows.count(r + 1));
  const ArtefactRecording run = apply_artefact(d.logged, "large_run", 4);
  ASSERT_EQ(run.truths.size(), 1u);
  EXPECT_GE(run.truths[0].last_row - run.truths[0].first_row + 1, 5u);
}

TEST(ZooArtefacts, BackwardsStampGoesBackwardsAndDropoutsAreWrittenAsSaid) {
  const ZooDraw d = draw(9, small({"white"}));
  const ArtefactRecording b = apply_artefact(d.logged, "backwards_stamp", 1);
  const std::size_t i = b.truths.at(0).first_row;
  EXPECT_LT(b.rec.time_s[i], b.rec.time_s[i - 1]);
  const ArtefactRecording e = apply_artefact(d.logged, "dropout_empty", 1);
  EXPECT_EQ(e.empty.size(), e.truths[0].last_row - e.truths[0].first_row + 1);
  const ArtefactRecording n = apply_artefact(d.logged, "dropout_nan", 1);
  EXPECT_NE(write_csv(n.rec, {}).find("nan"), std::string::npos);
}

TEST(ZooGenerator, APowerDrawUnderWhiteNoiseHasAnOracleFarAboveNinetyPercentAndANoiseDrawNone) {
  DrawLimits l = small({"white"});
  EXPECT_TRUE(std::isnan(draw(44, l).oracle_d));
  l.effect_truth = "twice_per_rev";
  l.effect_snr = 1.5;
  const ZooDraw d = draw(44, l);
  // Known signal in white noise: d^2 = the signal's sum of squares over both channels over the
  // noise's variance = 2 n x 1.5^2 (the SNR is the change's RMS over both channels).
  const double expected = 1.5 * std::sqrt(2.0 * static_cast<double>(d.rows));
  EXPECT_NEAR(d.oracle_d, expected, 0.1 * expected);
  EXPECT_GT(d.oracle_power, 0.999);
}

}  // namespace
}  // namespace gc::zoo
