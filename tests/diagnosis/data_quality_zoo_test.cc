// The data-quality stage against artefacts written by another hand (tests/diagnosis/zoo/
// artefacts.h, by a developer who never read diagnosis/): for each kind, several seeds, the
// finding of the right kind on the right channel covering the truth's rows within a tolerance.
// Empty and NaN cells are the reader's (their rows never reach the core) and are not tested here.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "diagnosis/data_quality.h"
#include "diagnosis/noise_estimate.h"
#include "diagnosis/polarity_flip.h"
#include "tests/diagnosis/zoo/artefacts.h"

namespace gc {
namespace {

constexpr std::size_t kRows = 2000;
constexpr std::size_t kTolerance = 2;  ///< rows the stage may be off at either end of a truth

/// A clean 10 Hz recording as a test cell logs it: torque steps and a misalignment sweep read
/// by noisy sensors, moments of about 100 kN·m, without noise (the model's prediction) when
/// `moment_noise` is false, with 2 kN·m of it otherwise (the same draws either way).
zoo::Channels clean_recording(std::uint64_t seed, bool moment_noise = true) {
  zoo::Rng rng(seed);
  zoo::Channels c;
  c.resize(kRows);
  for (std::size_t i = 0; i < kRows; ++i) {
    const double t = 0.1 * static_cast<double>(i);
    c.time_s[i] = t;
    c.torque_nm[i] = 2e5 * static_cast<double>(1 + (i / 200) % 5) + 500.0 * rng.normal();
    c.zeta_rad[i] = 0.003 * (1.2 + std::sin(0.01 * static_cast<double>(i))) + 2e-6 * rng.normal();
    c.beta_rad[i] = 0.2 * std::sin(0.003 * static_cast<double>(i)) + 1e-4 * rng.normal();
    c.speed_rpm[i] = 12.0 + 0.02 * rng.normal();
    c.temperature_c[i] = 30.0 + 0.001 * t + 0.05 * rng.normal();
    const double noise_y = 2000.0 * rng.normal(), noise_z = 2000.0 * rng.normal();
    c.msy_nm[i] = -0.3 * c.torque_nm[i] * c.zeta_rad[i] / 0.004 + (moment_noise ? noise_y : 0.0);
    c.msz_nm[i] = 3e4 * std::sin(0.007 * static_cast<double>(i)) + (moment_noise ? noise_z : 0.0);
  }
  return c;
}

std::vector<RecordedSample> samples(const zoo::Channels& c) {
  std::vector<RecordedSample> out(c.rows());
  for (std::size_t i = 0; i < c.rows(); ++i) {
    out[i].input = c.sample(i);
    out[i].measured = {c.msy_nm[i], c.msz_nm[i]};
  }
  return out;
}

/// The noise-free moments stand for the model's prediction: the residual the diagnosis would see.
Eigen::MatrixX2d residual(const zoo::Channels& measured, const zoo::Channels& prediction) {
  Eigen::MatrixX2d r(static_cast<Eigen::Index>(measured.rows()), 2);
  for (std::size_t i = 0; i < measured.rows(); ++i) {
    r.row(static_cast<Eigen::Index>(i)) << measured.msy_nm[i] - prediction.msy_nm[i], measured.msz_nm[i] - prediction.msz_nm[i];
  }
  return r;
}

std::vector<DataQualityFinding> findings_for(const zoo::ArtefactRecording& a, const zoo::Channels& prediction) {
  const std::vector<RecordedSample> obs = samples(a.rec);
  std::vector<DataQualityFinding> found = check_data_quality(obs).findings;
  std::vector<std::size_t> rows(obs.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
  for (DataQualityFinding& f : moment_polarity_flips(obs, rows, residual(a.rec, prediction))) found.push_back(std::move(f));
  if (auto spikes = spike_finding(outlier_positions(residual(a.rec, prediction)), obs, 7.0)) found.push_back(*spikes);
  return found;
}

/// The stage's name for a zoo kind.
std::string stage_kind(const std::string& zoo_kind) {
  if (zoo_kind == "dropout_zero") return "dropout";
  if (zoo_kind == "coarse_quantisation") return "quantisation";
  if (zoo_kind == "stamp_jitter" || zoo_kind == "duplicate_stamp" || zoo_kind == "backwards_stamp") return "irregular_time";
  return zoo_kind;
}

std::string describe(const std::vector<DataQualityFinding>& found) {
  std::string text;
  for (const DataQualityFinding& f : found) text += "  " + f.channel + " " + to_string(f.kind) + ": " + f.detail + "\n";
  return text;
}

/// A finding of the truth's kind on its channel whose rows cover the truth's to within kTolerance
/// at either end (a whole-record property: the kind and channel suffice).
bool found_truth(const zoo::ArtefactTruth& truth, const std::vector<DataQualityFinding>& found) {
  const std::string kind = stage_kind(truth.kind);
  const bool whole = kind == "quantisation" || truth.kind == "stamp_jitter";
  return std::any_of(found.begin(), found.end(), [&](const DataQualityFinding& f) {
    if (to_string(f.kind) != kind) return false;
    if (kind == "spike" ? f.channel.find(truth.channel) == std::string::npos : f.channel != truth.channel) return false;
    if (whole) return true;
    return std::any_of(f.spans.begin(), f.spans.end(), [&](const RowSpan& s) {
      return s.first_row <= truth.first_row + kTolerance && s.last_row + kTolerance >= truth.last_row &&
             s.first_row + kTolerance >= truth.first_row && s.last_row <= truth.last_row + kTolerance;
    }) || (kind == "clipped" || kind == "spike" || kind == "dropout"
               ? std::count_if(f.rows.begin(), f.rows.end(), [&](std::size_t r) {
                     return r >= truth.first_row && r <= truth.last_row;
                   }) == static_cast<std::ptrdiff_t>(truth.last_row - truth.first_row + 1)
               : false);
  });
}

class ZooArtefact : public ::testing::TestWithParam<std::string> {};

TEST_P(ZooArtefact, IsFoundWithItsKindChannelAndRows) {
  const std::string kind = GetParam();
  int found = 0, total = 0;
  std::string misses;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const zoo::Channels clean = clean_recording(100 + seed);
    const zoo::ArtefactRecording a = zoo::apply_artefact(clean, kind, seed);
    // An input rounded to a coarse grid cannot be told from set points (data_quality.h).
    if (kind == "coarse_quantisation" && a.truths.front().channel != "msy" && a.truths.front().channel != "msz") continue;
    const std::vector<DataQualityFinding> stage = findings_for(a, clean_recording(100 + seed, false));
    for (const zoo::ArtefactTruth& truth : a.truths) {
      ++total;
      if (found_truth(truth, stage)) ++found;
      else misses += "seed " + std::to_string(seed) + ": " + truth.channel + " " + truth.kind + " rows " +
                     std::to_string(truth.first_row) + "-" + std::to_string(truth.last_row) + " (" + truth.detail +
                     ") not found; the stage said:\n" + describe(stage);
    }
  }
  ASSERT_GT(total, 0);
  // At most one truth in fifty missed (an isolated spike whose neighbour the noise carries beyond half
  // the threshold is kept as possible structure: seed 6's msz spike at row 1646).
  EXPECT_GE(found, total - total / 50) << misses;
}

INSTANTIATE_TEST_SUITE_P(Kinds, ZooArtefact,
                         ::testing::Values("clipped", "stuck", "dropout_zero", "time_gap", "polarity_flip",
                                           "coarse_quantisation", "stamp_jitter", "duplicate_stamp",
                                           "backwards_stamp", "spike"));

TEST(ZooArtefact, RunsOfLargeResidualsAndRingingsAreNeverSpikes) {
  for (const std::string kind : {"large_run", "ringing"}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const zoo::Channels clean = clean_recording(200 + seed);
      const zoo::ArtefactRecording a = zoo::apply_artefact(clean, kind, seed);
      const std::vector<std::size_t> spikes = outlier_positions(residual(a.rec, clean_recording(200 + seed, false)));
      for (const zoo::ArtefactTruth& truth : a.truths) {
        const auto inside = std::count_if(spikes.begin(), spikes.end(), [&](std::size_t r) {
          return r >= truth.first_row && r <= truth.last_row;
        });
        EXPECT_EQ(inside, 0) << kind << " seed " << seed << " rows " << truth.first_row << "-" << truth.last_row;
      }
    }
  }
}

}  // namespace
}  // namespace gc
