// The data-quality stage (diagnosis/data_quality.h) on small recordings written here: each
// artefact found with its kind, channel and rows, and none on clean noise of several kinds.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "diagnosis/data_quality.h"
#include "diagnosis/noise_estimate.h"
#include "diagnosis/quantisation.h"

namespace gc {
namespace {

constexpr std::size_t kRows = 1000;
constexpr double kPeriodS = 0.01;
constexpr double kSigmaNm = 2000.0;

enum class Noise { gaussian, student_t, ar1, fine_quantised };

/// A moment sweep at torque set points (held in steps of 100 rows, as a designed sequence holds
/// them), moments of about 100 kN·m plus `noise` of sigma kSigmaNm.
std::vector<RecordedSample> recording(Noise noise, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::student_t_distribution<double> student(3.0);
  std::vector<RecordedSample> out(kRows);
  double ar[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < kRows; ++i) {
    RecordedSample& s = out[i];
    s.input.time_s = static_cast<double>(i) * kPeriodS;
    s.input.torque_nm = 1e5 * static_cast<double>(1 + i / 100);
    s.input.misalignment_rad = 0.004 * (1.0 + std::sin(static_cast<double>(i) * 0.02));
    s.input.direction_rad = 0.0;
    double e[2];
    for (int c = 0; c < 2; ++c) {
      switch (noise) {
        case Noise::gaussian: e[c] = kSigmaNm * normal(random); break;
        case Noise::student_t: e[c] = kSigmaNm / std::sqrt(3.0) * student(random); break;
        case Noise::ar1: ar[c] = 0.95 * ar[c] + kSigmaNm * std::sqrt(1.0 - 0.95 * 0.95) * normal(random); e[c] = ar[c]; break;
        case Noise::fine_quantised: e[c] = kSigmaNm * normal(random); break;
      }
    }
    s.measured.y_nm = -1e5 * std::cos(static_cast<double>(i) * 0.02) + e[0];
    s.measured.z_nm = 2e4 * std::sin(static_cast<double>(i) * 0.02) + e[1];
    if (noise == Noise::fine_quantised) {  // a 16-bit ADC over +-1.6 MN·m: 50 N·m, 2.5 % of sigma
      s.measured.y_nm = 50.0 * std::round(s.measured.y_nm / 50.0);
      s.measured.z_nm = 50.0 * std::round(s.measured.z_nm / 50.0);
    }
  }
  return out;
}

const DataQualityFinding* find(const DataQuality& q, DataQualityKind kind, const std::string& channel) {
  for (const DataQualityFinding& f : q.findings) if (f.kind == kind && f.channel == channel) return &f;
  return nullptr;
}

std::vector<std::size_t> range(std::size_t first, std::size_t last) {
  std::vector<std::size_t> rows;
  for (std::size_t r = first; r <= last; ++r) rows.push_back(r);
  return rows;
}

std::string kinds(const DataQuality& q) {
  std::string text;
  for (const DataQualityFinding& f : q.findings) text += f.channel + " " + to_string(f.kind) + ": " + f.detail + "\n";
  return text;
}

TEST(DataQuality, FindsNothingOnCleanNoiseOfSeveralKinds) {
  for (Noise noise : {Noise::gaussian, Noise::student_t, Noise::ar1, Noise::fine_quantised}) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const DataQuality q = check_data_quality(recording(noise, seed));
      EXPECT_TRUE(q.findings.empty()) << "noise " << static_cast<int>(noise) << " seed " << seed << "\n" << kinds(q);
      EXPECT_TRUE(q.excluded_rows.empty());
    }
  }
}

TEST(DataQuality, FindsNothingOnANoiseFreeRecordingThatHoldsStill) {
  // The moments of a model without noise repeat while the inputs hold: physics, not a frozen channel.
  std::vector<RecordedSample> r = recording(Noise::gaussian, 1);
  for (RecordedSample& s : r) {
    s.input.misalignment_rad = 0.004;
    s.measured.y_nm = -0.1 * s.input.torque_nm;
    s.measured.z_nm = 1e3;
  }
  const DataQuality q = check_data_quality(r);
  EXPECT_TRUE(q.findings.empty()) << kinds(q);
}

TEST(DataQuality, ANoiseFreeInputThatHoldsHalfTheTimeIsAProgrammeButANoisyOneFrozenIsStuck) {
  // A misalignment held while the direction turns, then ramped while the direction holds: each
  // input changes on about half the samples, smoothly. Its holds are the programme's.
  std::vector<RecordedSample> r = recording(Noise::gaussian, 4);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const bool turning = (i / 125) % 2 == 0;
    const double k = static_cast<double>(i % 125);
    r[i].input.misalignment_rad = turning ? 0.002 : 0.002 + 1e-5 * k;
    r[i].input.direction_rad = turning ? 0.01 * k : 0.0;
  }
  const DataQuality q = check_data_quality(r);
  EXPECT_TRUE(q.findings.empty()) << kinds(q);
  EXPECT_TRUE(q.excluded_rows.empty());
  // The same misalignment read by a probe with noise, frozen for 40 samples: an artefact.
  std::mt19937_64 random(5);
  std::normal_distribution<double> normal(0.0, 2e-6);
  for (RecordedSample& s : r) s.input.misalignment_rad += normal(random);
  for (std::size_t i = 500; i < 540; ++i) r[i].input.misalignment_rad = r[499].input.misalignment_rad;
  const DataQuality frozen = check_data_quality(r);
  const DataQualityFinding* f = find(frozen, DataQualityKind::stuck, "misalignment");
  ASSERT_NE(f, nullptr) << kinds(frozen);
  EXPECT_EQ(f->rows, range(499, 539));
}

TEST(DataQuality, ClippedSamplesAtTheRailAreExcludedWithTheirRows) {
  std::vector<RecordedSample> r = recording(Noise::gaussian, 2);
  double rail = -INFINITY;
  for (const RecordedSample& s : r) rail = std::max(rail, s.measured.y_nm);
  rail -= 8000.0;  // the crest of the sweep runs into the rail
  std::vector<std::size_t> clipped;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (r[i].measured.y_nm >= rail) { r[i].measured.y_nm = rail; clipped.push_back(i); }
  }
  ASSERT_GT(clipped.size(), 20u);
  const DataQuality q = check_data_quality(r);
  const DataQualityFinding* f = find(q, DataQualityKind::clipped, "msy");
  ASSERT_NE(f, nullptr) << kinds(q);
  EXPECT_EQ(f->rows, clipped);
  EXPECT_TRUE(f->excluded);
  EXPECT_EQ(q.excluded_rows, clipped);
  EXPECT_EQ(find(q, DataQualityKind::stuck, "msy"), nullptr) << "a rail's samples are claimed once";
  EXPECT_EQ(q.findings.size(), 1u) << kinds(q);
}

TEST(DataQuality, AFrozenChannelIsStuckButAShortTieIsNot) {
  std::vector<RecordedSample> r = recording(Noise::gaussian, 3);
  for (std::size_t i = 300; i < 340; ++i) r[i].measured.z_nm = r[299].measured.z_nm;  // holds its last reading
  r[601].measured.z_nm = r[600].measured.z_nm;  // two equal neighbours happen
  const DataQuality q = check_data_quality(r);
  const DataQualityFinding* f = find(q, DataQualityKind::stuck, "msz");
  ASSERT_NE(f, nullptr) << kinds(q);
  EXPECT_EQ(f->rows, range(299, 339));
  ASSERT_EQ(f->spans.size(), 1u);
  EXPECT_NEAR(f->spans[0].t_start_s, 2.99, 1e-9);
  EXPECT_NEAR(f->spans[0].t_end_s, 3.39, 1e-9);
  EXPECT_EQ(q.findings.size(), 1u) << kinds(q);
}

// A bridge that freezes for the last 60 % of a recording while the inputs move: its longest run is
// the artefact, not the channel's nature (counted with it, the ties made it look like a channel that
// repeats by design, and the diagnosis called 34 kN·m of misfit noise).
TEST(DataQuality, AChannelFrozenForMostOfTheRecordingIsStuck) {
  std::vector<RecordedSample> r = recording(Noise::gaussian, 13);
  for (std::size_t i = 400; i < r.size(); ++i) r[i].measured.z_nm = r[399].measured.z_nm;
  const DataQuality q = check_data_quality(r);
  const DataQualityFinding* f = find(q, DataQualityKind::stuck, "msz");
  ASSERT_NE(f, nullptr) << kinds(q);
  EXPECT_EQ(f->rows, range(399, 999));
  EXPECT_TRUE(f->excluded);
}

TEST(DataQuality, ZerosWhereTheLevelIsFarFromZeroAreDropouts) {
  std::vector<RecordedSample> r = recording(Noise::gaussian, 4);
  for (std::size_t i = 500; i <= 502; ++i) r[i].measured.y_nm = 0.0;
  r[800].measured.y_nm = 0.0;
  const DataQuality q = check_data_quality(r);
  const DataQualityFinding* f = find(q, DataQualityKind::dropout, "msy");
  ASSERT_NE(f, nullptr) << kinds(q);
  std::vector<std::size_t> expected = range(500, 502);
  expected.push_back(800);
  EXPECT_EQ(f->rows, expected);
  EXPECT_EQ(f->spans.size(), 2u);
  EXPECT_EQ(q.excluded_rows, expected);
}

TEST(DataQuality, TimeGapsAndDuplicatedStampsAreReportedAndKept) {
  std::vector<RecordedSample> r = recording(Noise::gaussian, 5);
  for (std::size_t i = 700; i < r.size(); ++i) r[i].input.time_s += 2.0;  // logging paused 2 s
  r[200].input.time_s = r[199].input.time_s;
  r[400].input.time_s = r[399].input.time_s;
  const DataQuality q = check_data_quality(r);
  const DataQualityFinding* gap = find(q, DataQualityKind::time_gap, "time");
  ASSERT_NE(gap, nullptr) << kinds(q);
  EXPECT_EQ(gap->rows, std::vector<std::size_t>{700});
  EXPECT_FALSE(gap->excluded);
  const DataQualityFinding* stamps = find(q, DataQualityKind::irregular_time, "time");
  ASSERT_NE(stamps, nullptr) << kinds(q);
  EXPECT_EQ(stamps->rows, (std::vector<std::size_t>{200, 400}));
  EXPECT_NE(stamps->detail.find("2 rows share their stamp"), std::string::npos) << stamps->detail;
  EXPECT_TRUE(q.excluded_rows.empty());
}

TEST(DataQuality, JitteredStampsAreReported) {
  std::vector<RecordedSample> r = recording(Noise::gaussian, 6);
  std::mt19937_64 random(6);
  std::uniform_real_distribution<double> jitter(-0.1 * kPeriodS, 0.1 * kPeriodS);
  for (RecordedSample& s : r) s.input.time_s += jitter(random);
  const DataQuality q = check_data_quality(r);
  const DataQualityFinding* f = find(q, DataQualityKind::irregular_time, "time");
  ASSERT_NE(f, nullptr) << kinds(q);
  EXPECT_NE(f->detail.find("jitters"), std::string::npos) << f->detail;
}

TEST(DataQuality, ATorqueTurningNegativePartwayIsCountedWithTheNegateAdvice) {
  std::vector<RecordedSample> r = recording(Noise::gaussian, 7);
  for (std::size_t i = 600; i < r.size(); ++i) r[i].input.torque_nm = -r[i].input.torque_nm;
  const DataQuality q = check_data_quality(r);
  const DataQualityFinding* f = find(q, DataQualityKind::polarity_flip, "torque");
  ASSERT_NE(f, nullptr) << kinds(q);
  EXPECT_EQ(f->rows, range(600, 999));
  EXPECT_TRUE(f->excluded);
  EXPECT_NE(f->detail.find("400 of 1000 rows"), std::string::npos) << f->detail;
  EXPECT_NE(f->detail.find("--negate torque"), std::string::npos) << f->detail;
  // The model refuses those rows itself: they are counted as refused, not removed here.
  EXPECT_TRUE(q.excluded_rows.empty());
  const std::vector<ExcludedRange> ranges = excluded_ranges(q.findings, range(600, 999), "torque", r);
  ASSERT_EQ(ranges.size(), 1u);
  EXPECT_EQ(ranges[0].span.first_row, 600u);
  EXPECT_EQ(ranges[0].span.last_row, 999u);
  EXPECT_NE(ranges[0].reason.find("polarity_flip torque"), std::string::npos) << ranges[0].reason;
}

TEST(DataQuality, ACoarseAdcStepIsReportedWithWhatItAddsToTheNoise) {
  std::vector<RecordedSample> r = recording(Noise::gaussian, 8);
  for (RecordedSample& s : r) s.measured.y_nm = 1000.0 * std::round(s.measured.y_nm / 1000.0);  // half a sigma
  const DataQuality q = check_data_quality(r);
  const DataQualityFinding* f = find(q, DataQualityKind::quantisation, "msy");
  ASSERT_NE(f, nullptr) << kinds(q);
  EXPECT_FALSE(f->excluded);
  EXPECT_NE(f->detail.find("grid of 1.00 kN·m"), std::string::npos) << f->detail;
  EXPECT_EQ(q.findings.size(), 1u) << kinds(q);
  // Five levels among ten values: a grid (at most half the values distinct), its step within rounding.
  const std::optional<double> step = quantisation_step(std::vector<double>{0.0, 0.3, 0.9, 0.3, 1.2, 0.6, 0.6, 0.0, 0.9, 1.2});
  ASSERT_TRUE(step.has_value());
  EXPECT_NEAR(*step, 0.3, 1e-12);
}

TEST(DataQuality, OnlyIsolatedSamplesAreSpikesARingingIsStructure) {
  std::mt19937_64 random(9);
  std::normal_distribution<double> normal(0.0, kSigmaNm);
  Eigen::MatrixX2d residual(kRows, 2);
  for (Eigen::Index i = 0; i < residual.rows(); ++i) residual.row(i) << normal(random), normal(random);
  // A lightly damped resonance ringing for 14 samples after a torque step at row 300.
  for (int k = 0; k < 14; ++k) residual(300 + k, 0) += 40000.0 * std::exp(-0.05 * k) * (k % 2 ? -1.0 : 1.0);
  residual(600, 1) += 30000.0;                           // a spike
  residual(800, 0) += 30000.0;                           // two in a row are still spikes
  residual(801, 0) -= 30000.0;
  EXPECT_EQ(outlier_positions(residual), (std::vector<std::size_t>{600, 800, 801}));
}

}  // namespace
}  // namespace gc
