// The noise zoo through the CLI (tests/diagnosis/zoo/): a FIXED sample of 50 noise-only draws
// (master seed 20250601), each diagnosed as a user runs it with the model the recording was made
// from. Any claim is false, and none is allowed (issue 37). Rows are capped at 60,000 for CI time (the
// full range, up to 200,000 rows, is gc_noise_zoo's). Diagnose's time is driven by whether it
// searches, not by rows: on draws it calls noise it takes 0.4-14 s (174,791 rows: 13.6 s), on
// draws where it claims 37-100 s at -j 1. The 50 draws take some 2-4 minutes on two cores
// (TIMEOUT 1800 leaves room for a busy machine).
// Two draws at a time, diagnose -j 1 each.
// A failure names every claimed draw: rerun it alone with
//   gc_noise_zoo --gearcoupling build/clients/cli/gearcoupling --seed 20250601 --max-rows 60000 --only K
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <mutex>
#include <thread>
#include <utility>

#include "tests/diagnosis/zoo/harness.h"
#include "tests/diagnosis/zoo/zoo.h"

namespace gc::zoo {
namespace {

constexpr std::uint64_t kMasterSeed = 20250601;
constexpr std::size_t kDraws = 50;
constexpr std::size_t kMaxRows = 60000;

struct ZooRun {
  std::vector<ZooDraw> draws;
  std::vector<DiagnoseOutcome> outcomes;
  std::size_t claims = 0, errors = 0;
  std::string report;  ///< each claimed or failed draw, with its description and numbers
};

/// `count` draws of master seed `master` under `lim`, from its draw `first` on, each diagnosed
/// through the CLI with the model it was made from, two at a time (diagnose -j 1 each).
ZooRun run_zoo(std::uint64_t master, std::size_t count, const DrawLimits& lim, std::size_t first = 0) {
  const auto root = std::filesystem::temp_directory_path() / ("gc_zoo_test_" + std::to_string(::getpid()) + "_" +
                                                              std::to_string(master));
  ZooRun run;
  run.draws.resize(count);
  run.outcomes.resize(count);
  std::atomic<std::size_t> next{0};
  std::mutex print;
  auto worker = [&]() {
    for (std::size_t k; (k = next++) < count;) {
      ZooDraw d = draw(draw_seed(master, first + k), lim);
      const auto dir = root / ("draw_" + std::to_string(k));
      const auto model = write_choice(d.model, dir);
      std::ofstream(dir / "recording.csv", std::ios::binary) << d.csv;
      d.csv.clear();
      run.outcomes[k] = run_diagnose(GC_GEARCOUPLING_PATH, dir / "recording.csv", model, 1);
      run.draws[k] = std::move(d);
      if (!std::getenv("GC_ZOO_KEEP")) std::filesystem::remove_all(dir);
      std::lock_guard lock(print);
      const DiagnoseOutcome& o = run.outcomes[k];
      std::printf("[%zu] %s %s (%.1f s) %s\n", first + k, o.error ? "ERROR" : o.claim ? "CLAIM" : "noise", o.outcomes.c_str(),
                  o.wall_s, run.draws[k].description.c_str());
      std::fflush(stdout);
    }
  };
  std::thread a(worker), b(worker);
  a.join();
  b.join();
  if (!std::getenv("GC_ZOO_KEEP")) std::filesystem::remove_all(root);
  for (std::size_t k = 0; k < count; ++k) {
    const DiagnoseOutcome& o = run.outcomes[k];
    if (o.error) {
      ++run.errors;
      run.report += "  K=" + std::to_string(first + k) + " ERROR exit " + std::to_string(o.exit_code) + ": " + o.stderr_tail +
                    "\n    " + run.draws[k].description + "\n";
    }
    if (!o.claim) continue;
    ++run.claims;
    std::string names;
    for (const auto& c : o.claimed) names += (names.empty() ? "" : ", ") + c;
    run.report += "  K=" + std::to_string(first + k) + " " + run.draws[k].description + "\n    outcomes: " + o.outcomes +
                  "\n    claimed: " + (names.empty() ? "(none named)" : names) + "\n    numbers: " + o.numbers + "\n";
  }
  std::printf("noise zoo: %zu false claims and %zu errors in %zu draws (master seed %llu; 95 %% upper bound %.1f %%)\n",
              run.claims, run.errors, count, static_cast<unsigned long long>(master),
              100 * clopper_pearson_upper(run.claims, count - run.errors));
  return run;
}

TEST(NoiseZoo, FiftyNoiseOnlyDrawsClaimNothing) {
  DrawLimits lim;
  lim.max_rows = kMaxRows;
  const ZooRun run = run_zoo(kMasterSeed, kDraws, lim);
  // Issue 37's target: no claim and no error. Draw 35 (a compliance on a torque transducer's and
  // filtered probes' noise: errors in the inputs attenuate how the data follow them) is noise since
  // every effect must beat the model fed its inputs read back from their noise (input_noise_check.h);
  // draw 40 (a misalignment held while the direction turns, read as a stuck sensor) is diagnosed
  // since a smooth programme's holds are no artefact (recorded_channels.h).
  EXPECT_EQ(run.claims, 0u) << "diagnose claimed physics on " << run.claims << " of " << kDraws
                                          << " noise-only recordings (the truth is exactly the model it was given):\n"
                                          << run.report;
  EXPECT_EQ(run.errors, 0u) << run.report;
}

// Noise on the input channels alone (proximity probes, a torque transducer, each with random
// levels and filters): the model carries it into its prediction, and an average of the inputs
// takes it out again, but there is no lag and no physics to claim (input_noise_check.h). Fresh
// draws of a master seed no rule was designed on.
TEST(NoiseZoo, NoisyInputSensorsAloneAreNoLagAndNoPhysics) {
  std::size_t claims = 0, errors = 0, draws = 0;
  std::string report;
  for (const char* family : {"probes", "torque_sensor"}) {
    DrawLimits lim;
    lim.min_rows = 3000;
    lim.max_rows = 20000;
    lim.only_families = {family};
    const ZooRun run = run_zoo(20261129, 4, lim);
    claims += run.claims;
    errors += run.errors;
    draws += run.draws.size();
    report += run.report;
  }
  // Measured 0 of 8. A 1.65 Hz rig where moment_delay averaged over a revolution of half a
  // minute, beyond the centred window's 5 s, got a claim until timing effects too had to beat the
  // model fed its inputs read back from their noise.
  EXPECT_EQ(claims, 0u) << claims << " of " << draws << " recordings with noisy inputs got a claim:\n" << report;
  EXPECT_EQ(errors, 0u) << report;
}

// Draws of fresh 500-draw measurements that a rule made since then turned from a claim to noise,
// each diagnosed as the zoo benchmark does: seed 20261211 draw 74, proximity-probe noise at 1.5 mrad
// and 750 Hz, where a formula's gain of -0.9 on the model's own M_sz' took 56 % of the held-out
// error (the formula must beat the model fed its inputs read back, input_noise_check.h); draw 161,
// brown and mains noise, where a fit re-solved from a point the model cannot predict failed the
// diagnosis (effect_fit.h); seed 20261220 draw 143, brown noise on a torque staircase, where a gain
// and offset of both channels took 26 % of the held-out error at t = 6.9 through interleaved folds
// and did not carry to whole fifths (claim_carries.h); seed 20261225 draw 108, a wandering zero
// across the gap that a misalignment held by the programme left when it was cut out as stuck
// (programme_holds.h); draw 425, a torque held the same way, which left 334 of 1,222 rows and an
// error; draw 362, 60 Hz aliased to 16 Hz by a 38 Hz DAQ beside a mesh order at some of the shaft's
// speeds (mains_pickup.h); seed 20261227 draw 71, 50 Hz pickup taken for the rig ringing at 50.7 Hz;
// brown noise called "unexplained" (the signature's bins of inputs that move with time took the
// walk, and carried to whole fifths): seed 20261236 draw 191 (109,671 rows, the noise read as 33 N·m
// under a 4.8 kN·m walk), seed 20261238 draws 63 (3,731 rows in 6 s) and 370 (with a torque
// transducer's noise and jittered stamps): the signature pays the surrogate test as an effect does
// (signature_held_out.h, signature_design); seed 20261243 draw 35, a zero wandering over 20 s of
// 108 s, where a compliance fitted past its plausible box, a gain and offset and a torque
// calibration did not carry to whole fifths, and the fourth claimable, a refined friction taking
// 4 %, went untested (three at most were tried): every claimable one is (claim_carries.h);
// seed 20261281 draw 445, a torque transducer's white noise at 399 Hz, where a ringing of the
// torque at 1.06 Hz (a smoother of the noisy torque) found on the dense rows took 15 % of their
// held-out error: the dense rows' formula too must beat the model fed its inputs read back;
// seed 20261284 draw 495, an AR(2) resonance 2.3 Hz wide at 12.2 Hz, whose peak the surrogates
// brought down as a line, so a cycle at its top was claimed at p = 0 (surrogate_test.h: a line is
// narrow); seed 20261317 draw 22, brown noise alone on 370 s of a ramp, a staircase, a hold, a
// wander and a sweep, where a gain and offset took 62 % of the walk's variation and none of 12,000
// stationary surrogates reached it: under a walk the share prewhitened judges alone
// (surrogate_test.cc, statistics_for). The rate is docs/benchmarks.md's; these keep the mechanisms
// fixed.
TEST(NoiseZoo, DrawsThatFreshMeasurementsClaimedOrFailedOnAreNoise) {
  std::size_t claims = 0, errors = 0;
  std::string report;
  for (const auto& [master, k] : {std::pair<std::uint64_t, std::size_t>{20261211, 74}, {20261211, 161}, {20261220, 143},
                                  {20261225, 108}, {20261225, 425}, {20261225, 362}, {20261227, 71},
                                  {20261236, 191}, {20261238, 63}, {20261238, 370}, {20261243, 35},
                                  {20261281, 445}, {20261284, 495}, {20261317, 22}}) {
    const ZooRun run = run_zoo(master, 1, DrawLimits{}, k);
    claims += run.claims;
    errors += run.errors;
    report += run.report;
  }
  EXPECT_EQ(claims, 0u) << report;
  EXPECT_EQ(errors, 0u) << report;
}

/// A power table's draw (`seed`, draw `k`, `effect` hidden at SNR 1.5, 1,000-20,000 rows: the
/// generator's own, written without reading the diagnosis), diagnosed by the CLI as a user runs it.
struct PowerDraw {
  ZooDraw draw;
  DiagnoseOutcome out;
  std::string json;  ///< diagnose --json as printed
};

PowerDraw diagnosed_power_draw(std::uint64_t seed, std::size_t k, const std::string& effect) {
  DrawLimits lim;
  lim.min_rows = 1000;
  lim.max_rows = 20000;
  lim.effect_truth = effect;
  lim.effect_snr = 1.5;
  PowerDraw p{draw(draw_seed(seed, k), lim), {}, {}};
  const auto dir = std::filesystem::temp_directory_path() / ("gc_zoo_power_" + effect + "_" + std::to_string(::getpid()));
  const auto model = write_choice(p.draw.model, dir);
  std::ofstream(dir / "recording.csv", std::ios::binary) << p.draw.csv;
  p.out = run_diagnose(GC_GEARCOUPLING_PATH, dir / "recording.csv", model, 1);
  std::ifstream json_file(dir / "diagnose.json", std::ios::binary);
  p.json.assign(std::istreambuf_iterator<char>(json_file), std::istreambuf_iterator<char>());
  std::filesystem::remove_all(dir);
  return p;
}

/// Whether the draw's diagnosis named `name` first, with what it did otherwise.
::testing::AssertionResult named_first(const PowerDraw& p, std::initializer_list<std::string> names) {
  if (p.out.error) return ::testing::AssertionFailure() << p.out.stderr_tail;
  if (p.out.first_claim.empty()) return ::testing::AssertionFailure() << p.out.outcomes << "\n" << p.draw.description;
  if (std::find(names.begin(), names.end(), p.out.first_claim.front()) == names.end()) {
    return ::testing::AssertionFailure() << p.out.first_claim.front() << " first: " << p.out.outcomes << ": " << p.out.numbers;
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult named_first(const PowerDraw& p, const std::string& name) { return named_first(p, {name}); }

/// The value diagnose --json gives `parameter` where it first names it; NaN when it does not.
double first_value_of(const std::string& json, const std::string& parameter) {
  const std::size_t name = json.find("\"" + parameter + "\"");
  const std::size_t at = name == std::string::npos ? name : json.find("\"value\":", name);
  return at == std::string::npos ? std::nan("") : std::strtod(json.c_str() + at + 8, nullptr);
}

// Power: a misalignment scale of -0.24 (the hidden effect written from the physics in
// hidden_effects.cc) under slow heteroscedastic noise at SNR 1.5, on a torque staircase of 3,252
// rows (power table seed 20261214, draw 1). The cost in the scale is a staircase with a narrow
// valley at the truth; the fit stopped on a step at -0.17 and a gain and offset of both channels
// (four parameters, 4.07 kN·m held out against the truth's 3.80) was named first, until a lone
// parameter is also scanned over its box (effect_fit.cc, scanned_start).
TEST(NoiseZooPower, AMisalignmentScaleInItsNarrowValleyIsNamedFirst) {
  const PowerDraw p = diagnosed_power_draw(20261214, 1, "misalignment_scale");
  ASSERT_FALSE(p.out.error) << p.out.stderr_tail;
  ASSERT_FALSE(p.out.first_claim.empty()) << p.out.outcomes << "\n" << p.draw.description;
  EXPECT_EQ(p.out.first_claim.front(), "misalignment_scale")
      << p.out.outcomes << ": " << p.out.numbers << "\n" << p.draw.description;
}

// A speed drag of 1.7 kN·m/rpm under the zoo's heteroscedastic, demodulated and slowly modulated
// noise at SNR 1.5, on two ramps over which speed rises 4.5 rpm and falls 6.5 (power table seed
// 20261216, draw 0). A refined friction takes most of it (35 % of the held-out error against the
// speed terms' 44 %) and is claimed first, physics first. The verdict showed the speed terms,
// better by a block-paired t of 9.7, as "another reading of the same residual that this data
// cannot tell from it": it must say they do better.
TEST(NoiseZooPower, AFormulaBetterThanTheClaimedEffectIsNotCalledItsEqual) {
  const PowerDraw p = diagnosed_power_draw(20261216, 0, "speed_drag");
  ASSERT_FALSE(p.out.error) << p.out.stderr_tail;
  ASSERT_FALSE(p.out.first_claim.empty()) << p.out.outcomes << "\n" << p.draw.description;
  EXPECT_EQ(p.out.first_claim.front(), "friction") << p.out.outcomes << ": " << p.out.numbers;
  EXPECT_NE(p.json.find("A formula of physical terms does better on held-out data"), std::string::npos)
      << p.json.substr(0, 4000);
  EXPECT_NE(p.json.find("speed_on_z"), std::string::npos) << p.json.substr(0, 4000);
  EXPECT_EQ(p.json.find("cannot tell from it"), std::string::npos) << p.json.substr(0, 4000);
}

// A speed drag of 454 N·m/rpm at -1.22 rad (156 on M_sy', -426 on M_sz') under band-pass noise at
// SNR 1.5, the shaft at 5-14 rpm over a ramp, a sweep, a hold, a staircase and a wander, 19,336 rows
// (power table seed 20261253, draw 9). Its two speed terms match the truth, 2.30 kN·m held out
// against the noise's 2.41, yet they failed the surrogate test (p = 1: judged on their ripple alone,
// a fifth of the noise, against surrogates given the residual's own rise, which is the drag's), and
// a gain and offset of both channels (four parameters, 2.36 kN·m, t = 5.5 behind them) was claimed
// first, physics first. The level they move is judged as an effect's is, and a formula better than
// the effect with no more parameters stands first.
TEST(NoiseZooPower, TwoSpeedTermsBetterThanAGainAndOffsetStandFirst) {
  const PowerDraw p = diagnosed_power_draw(20261253, 9, "speed_drag");
  ASSERT_NE(p.draw.description.find("0.4541 kN·m per rpm at -1.22 rad"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, "expression"));
  EXPECT_NEAR(first_value_of(p.json, "speed_on_y"), 156.0, 0.05 * 156.0) << p.json.substr(0, 3000);
  EXPECT_NEAR(first_value_of(p.json, "speed_on_z"), -426.0, 0.05 * 426.0) << p.json.substr(0, 3000);
  // The verdict's words, its numbers aside (they are asserted above, to a tolerance).
  EXPECT_NE(p.json.find("better than any effect of the library (the best effect, channel_gain_offset, lowers it"),
            std::string::npos)
      << p.json.substr(0, 3000);
  EXPECT_NE(p.json.find("and could be claimed; the formula, with 2 parameters against its 4, predicts the held-out rows "
                        "better"),
            std::string::npos)
      << p.json.substr(0, 3000);
}

// A speed drag of 1.38 kN·m/rpm at -0.20 rad (1.35 on M_sy', -0.27 on M_sz') under an AR(1) of
// 0.035 s at SNR 1.5, 17,295 rows at 174 Hz over two wanders and a ramp (power table seed 20261310,
// draw 3). The formula found the speed on M_sy' (t = 22) and a speed-dependent turn of the moment,
// but also a misalignment rate (t = 1.2) and twice per revolution (t = 0.9 and 0.4): five terms,
// 5.19 kN·m held out at t = 3.4 against a gain and offset of both channels (four parameters, 5.29),
// which was claimed first, physics first, and the next round found only noise. A formula keeps only
// terms that stand out of their errors, and two terms better than four by t = 2.99 stand first.
TEST(NoiseZooPower, ASpeedDragsTwoTermsStandFirstOnceTheTermsWithinTheirErrorsAreDropped) {
  const PowerDraw p = diagnosed_power_draw(20261310, 3, "speed_drag");
  ASSERT_NE(p.draw.description.find("1.381 kN·m per rpm at -0.20 rad"), std::string::npos) << p.draw.description;
  ASSERT_TRUE(named_first(p, "expression"));
  for (const std::string& name : p.out.first_claim) {
    if (name == "expression") continue;  // the claim, and its record beside the verdict
    EXPECT_NE(name.find("speed"), std::string::npos) << name << ": " << p.out.numbers;
  }
  EXPECT_NEAR(first_value_of(p.json, "speed_on_y"), 1353.0, 0.1 * 1353.0) << p.json.substr(0, 3000);
}

// An assembly misalignment of 0.030 xi under brown noise alone (3.1 kN·m rms) at SNR 1.5, 11,579
// rows at 978 Hz over torque staircases, sweeps and a turn (power table seed 20261316, draw 5). It
// cut 41 % of the held-out error at t = 7.2, yet failed the surrogate test (p = 1 in a family of
// 15): a walk explains a slow design about as well. Prewhitened, the torque steps' jumps stand
// among the walk's increments (surrogate_test.h), and it is claimed, its amplitude within a
// fifth. The thermal growth beside it (a direction and a reference temperature fitted to the
// same steps) is alike on held-out error, and the simpler is named first.
TEST(NoiseZooPower, AnAssemblyMisalignmentUnderBrownNoiseIsFoundByItsSteps) {
  const PowerDraw p = diagnosed_power_draw(20261316, 5, "assembly_misalignment");
  ASSERT_NE(p.draw.description.find("zeta0 0.030 xi at 0.77 rad"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, "assembly_misalignment")) << p.out.numbers;
  // 0.030 xi of this coupling's 13.1 mrad jam angle (0.0448 xi is 0.588 mrad in its draw 5).
  EXPECT_NEAR(first_value_of(p.json, "zeta0_rad"), 3.94e-4, 0.2 * 3.94e-4) << p.json.substr(0, 3000);
  EXPECT_NEAR(first_value_of(p.json, "beta0_rad"), 0.77, 0.1) << p.json.substr(0, 3000);
}

// A speed drag of 0.58 kN·m/rpm on a speed that ramps from 4 to 9 rpm, under Laplace and GARCH
// noise (white, heavy-tailed), 4,027 rows at 2.22 Hz exported in other units (power table seed
// 20261299, draw 7). One speed term, 591 N·m/rpm on M_sz', cut the held-out error 45 % (t = 28.6),
// yet failed the surrogate test (p = 0.64): its surrogates were given the residual's own rise, the
// drag's. One chosen term is now judged against the leftover's rise, as an effect is.
TEST(NoiseZooPower, OneSpeedTermOnASpeedRampIsNotJudgedAgainstItsOwnRise) {
  const PowerDraw p = diagnosed_power_draw(20261299, 7, "speed_drag");
  ASSERT_NE(p.draw.description.find("0.58 kN·m per rpm at 1.54 rad"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, "expression"));
  EXPECT_NEAR(first_value_of(p.json, "speed_on_z"), 580.0, 0.1 * 580.0) << p.json.substr(0, 3000);
}

// A speed drag of 0.284 kN·m/rpm at -0.18 rad (279 on M_sy', -51 on M_sz') under Student's t
// noise, the tachometer noisy, 9,978 rows at 52 Hz over a misalignment staircase (power table seed
// 20261329, draw 4). The formula found both speed terms (44 % of the held-out error, t = 25.8), yet
// failed the surrogate test (p = 0.38): the test's own choice of two terms on the residual took
// speed on M_sy' and t^3 on M_sz', two time profiles, so the surrogates were given the residual's
// own rise, the drag's. The rise is judged by the profiles of the terms claimed.
TEST(NoiseZooPower, ASpeedDragsTwoTermsAreJudgedByTheirOwnProfile) {
  const PowerDraw p = diagnosed_power_draw(20261329, 4, "speed_drag");
  ASSERT_NE(p.draw.description.find("0.284 kN·m per rpm at -0.18 rad"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, "expression")) << p.out.numbers;
  EXPECT_NEAR(first_value_of(p.json, "speed_on_y"), 279.0, 0.1 * 279.0) << p.json.substr(0, 3000);
  EXPECT_NEAR(first_value_of(p.json, "speed_on_z"), -51.0, 0.2 * 51.0) << p.json.substr(0, 3000);
}

// A weight (an M_sy' offset of 17.4 kN·m rms) under a zero wandering with tau 5.7 s on 12.5 s, a
// moving average and torque-heteroscedastic noise, 2,407 rows (power table seed 20261258, draw 2).
// A formula of the offset and two terms that followed the wander through the sweep (3 parameters,
// 11.23 kN·m held out) beat the gain and offset of both channels (4 parameters, 11.37) by t = 3.7
// on the interleaved folds, and stood first as the simpler and better. Its edge does not carry to
// whole fifths, so the offset is named.
TEST(NoiseZooPower, AFormulaWhoseEdgeFollowsAWanderDoesNotTakeTheOffsetsPlace) {
  const PowerDraw p = diagnosed_power_draw(20261258, 2, "weight");
  ASSERT_NE(p.draw.description.find("wandering zero OU tau 5.65 s"), std::string::npos) << p.draw.description;
  ASSERT_TRUE(named_first(p, {"channel_gain_offset", "self_weight"}));
  EXPECT_NEAR(first_value_of(p.json, "offset_y_nm"), -20.9e3, 2.0e3) << p.json.substr(0, 3000);
}

// A heavier hub, an offset of 4.7 kN·m on M_sy' (1.5 times the noise), under a hidden AR(1) of phi
// 0.982 (2.7 times its white part), a random telegraph and a sample-and-hold, 1,293 rows at 30.3 Hz
// (power table seed 20261263, draw 7). The offset took 44 % of the held-out error at t = 21, yet its
// level was judged against the spread of 21 block means itself: p = 0.033 in the family, no claim.
// The means were nearly independent (the correlation is shorter than a block), so the level's
// standard error is their spread over sqrt(21), inflated only by a 1 % bound on their correlation
// (surrogate_test.h, level_standard_error).
TEST(NoiseZooPower, AnOffsetOverBlockMeansNearlyIndependentIsJudgedOnItsStandardError) {
  const PowerDraw p = diagnosed_power_draw(20261263, 7, "weight");
  ASSERT_NE(p.draw.description.find("hidden ar1 phi 0.982"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, {"self_weight", "channel_gain_offset"}));
}

// A compliance beyond its plausible range: the mesh at 0.121 of eq 5's stiffness (rim 12.4 C, scaled
// x1.15 to reach SNR 1.5) under AR(1) noise at phi 0.984 with jittered stamps, 2,042 rows on a
// torque staircase (power table seed 20261237, draw 0). The fit ended on the plausible box's edge
// (0.6), the box widened to the physical bound 0.1, and the descent from the edge stopped on the
// staircase's first step at 0.593 (-26 % held out): a gain and offset of both channels (-33 %)
// was named first. The widened box is scanned as the plausible one is (effect_fit.cc,
// widen_where_on_edge): compliance first, its factor within a fifth of the truth.
TEST(NoiseZooPower, ACompliancePastItsPlausibleRangeIsScannedWhereTheBoxWidens) {
  const PowerDraw p = diagnosed_power_draw(20261237, 0, "compliance");
  ASSERT_NE(p.draw.description.find("mesh at 0.121"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, "compliance"));
  EXPECT_NEAR(first_value_of(p.json, "stiffness_factor"), 0.121, 0.2 * 0.121) << p.json.substr(0, 3000);
}

// Torque gains past the plausible range of a torque calibration's slope (+-5 %), -12.0 % and
// -30.1 % (drawn -1.4 % and -2.1 %, scaled to reach SNR 1.5), under a sample-and-hold beside noise
// correlated across channels, and under a hidden AR(1) beside a telegraph with jittered stamps
// (power table seed 20261295, draws 4 and 8: 9,251 rows at 10.5 Hz, 16,798 at 2.47 Hz). The box
// widened and its descent from the edge, ten steps at the fine derivative, stopped in the long
// valley of slope and curvature (the teeth summed step with the torque): 5,459 and 17,145 N·m held
// out against a gain and offset of both channels' 5,403 and 16,634, which was named first. The
// widened box's descent goes on at coarser derivatives (effect_fit.cc, widen_where_on_edge): 5,364
// and 16,518, the torque calibration named, the larger gain's slope within a tenth of the truth.
TEST(NoiseZooPower, ATorqueGainPastItsPlausibleRangeIsFollowedAtCoarserDerivatives) {
  const PowerDraw small = diagnosed_power_draw(20261295, 4, "torque_gain");
  ASSERT_NE(small.draw.description.find("gain -12.03 %"), std::string::npos) << small.draw.description;
  EXPECT_TRUE(named_first(small, "torque_calibration"));
  const PowerDraw large = diagnosed_power_draw(20261295, 8, "torque_gain");
  ASSERT_NE(large.draw.description.find("gain -30.10 %"), std::string::npos) << large.draw.description;
  EXPECT_TRUE(named_first(large, "torque_calibration"));
  EXPECT_NEAR(first_value_of(large.json, "slope_error"), -0.301, 0.1 * 0.301) << large.json.substr(0, 3000);
}

// One turn of the misalignment's direction at a steady torque, under demodulated and spiky noise,
// 7,128 rows at 80.9 Hz (power table seed 20261270, draw 0). There anything that scales the
// moments fits alike: a mesh at 0.451 of eq 5's stiffness (touch-up x0.92) is fitted at 0.50, a
// torque gain of 10.6 % as a torque calibration with its slope at 0.050, and a gain and offset of
// both channels (four parameters, its gains within their plausible 10 %) fits either within 1 %
// held out. The gain and offset was named first: the simpler effects, a little past their plausible
// ranges, were never its alike. Among candidates the data cannot tell apart, fewer parameters
// outrank a plausible range (claim_order.h, put_simplest_alike_first), and the verdict names the
// gain and offset beside them with the experiment that separates them.
TEST(NoiseZooPower, ASimplerEffectPastItsPlausibleRangeGoesBeforeAnAlikeGainAndOffset) {
  const PowerDraw compliance = diagnosed_power_draw(20261270, 0, "compliance");
  ASSERT_NE(compliance.draw.description.find("mesh at 0.451"), std::string::npos) << compliance.draw.description;
  EXPECT_TRUE(named_first(compliance, "compliance"));
  EXPECT_NEAR(first_value_of(compliance.json, "stiffness_factor"), 0.451, 0.2 * 0.451) << compliance.json.substr(0, 3000);
  const std::size_t alike = compliance.json.find("\"alike\": [");
  ASSERT_NE(alike, std::string::npos) << compliance.json.substr(0, 3000);
  EXPECT_LT(compliance.json.find("\"channel_gain_offset\"", alike), compliance.json.find("\"signature\"", alike))
      << compliance.out.outcomes;
  const PowerDraw gain = diagnosed_power_draw(20261270, 0, "torque_gain");
  ASSERT_NE(gain.draw.description.find("gain +10.57 %"), std::string::npos) << gain.draw.description;
  EXPECT_TRUE(named_first(gain, "torque_calibration"));
}

// A friction refined on a hold then a ramp, under a demodulator's noise, 1,430 rows at 2.26 Hz on
// the downwind coupling (power table seed 20261278, draw 5). It and a gain and offset of both
// channels fit alike (328 against 326 N·m held out, corrections correlated r = 0.996); of friction's
// four parameters the data determines two (mu0, mu_low_torque: the reference torque and the
// misalignment's share are held at the model's value), against the gain and offset's four. Counted
// by what they fit, friction is the simpler and is named, the gain and offset beside it.
TEST(NoiseZooPower, ParametersHeldAtTheModelsValueDoNotCountAgainstTheSimplerEffect) {
  const PowerDraw p = diagnosed_power_draw(20261278, 5, "friction");
  ASSERT_NE(p.draw.description.find("hold>ramp"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, "friction"));
  EXPECT_NE(p.out.outcomes.find("indistinguishable"), std::string::npos) << p.out.outcomes;
}

// An ADC step of 5.2 kN·m on M_sy' (1.74 times the noise; another hand's adc_step family) under
// slow resonant and GARCH noise, 3,265 rows at 2.98 Hz (power table seed 20261219, draw 1). Where
// most neighbours are equal, the running median's deviations are the model's slow change, and every
// step of one ADC count stood 7 robust deviations out: 652 rows were excluded as isolated spikes.
// Judged against the rounding noise (q / sqrt(12)) at least, a step is no spike.
//
// The same draw's hidden weight, an offset of 4.5 kN·m on M_sy' (1.5 times the noise), was then
// "noise": the residual's mean square was 0.87 times the noise's estimate, heavy tails included,
// where 2.24 times was needed. Its level stands 90 long-run errors from zero
// (level_standard_errors): the round searches, and a weight is named first.
TEST(NoiseZooPower, AnAdcStepIsNotTakenForSpikesAndTheOffsetBesideItIsFound) {
  const PowerDraw p = diagnosed_power_draw(20261219, 1, "weight");
  ASSERT_NE(p.draw.description.find("ADC step"), std::string::npos) << p.draw.description;
  ASSERT_FALSE(p.out.error) << p.out.stderr_tail;
  const std::size_t at = p.json.find("\"outlier_rows\":");
  ASSERT_NE(at, std::string::npos) << p.json.substr(0, 2000);
  const long outliers = std::strtol(p.json.c_str() + at + 15, nullptr, 10);
  EXPECT_LE(outliers, 10) << p.draw.description;  // of 3,265 rows
  EXPECT_NE(p.json.find("quantisation"), std::string::npos);
  ASSERT_FALSE(p.out.first_claim.empty()) << p.out.outcomes << "\n" << p.draw.description;
  EXPECT_NE(p.out.first_claim.front().find("weight"), std::string::npos) << p.out.outcomes << ": " << p.out.numbers;
}

// The generator's continuous quarter sums are the change from the paper's sawtooth scaled to reach
// the SNR (x2.25 here, under resonant, spiky and cross-correlated noise: power table seed 20261219,
// draw 2). As a switch, the effect could take only the change itself: a spacing error was named
// first. With the share of the sawtooth smoothed away as its parameter, it is named and the share
// is the generator's within 10 %.
TEST(NoiseZooPower, TheSawtoothsChangeScaledIsNamedWithItsShare) {
  const PowerDraw p = diagnosed_power_draw(20261219, 2, "continuous_quarter_sums");
  EXPECT_TRUE(named_first(p, "continuous_quarter_sums"));
  const std::size_t lambda_at = p.draw.description.find("lambda ");
  ASSERT_NE(lambda_at, std::string::npos) << p.draw.description;
  const double lambda = std::strtod(p.draw.description.c_str() + lambda_at + 7, nullptr);  // 2.25
  EXPECT_NEAR(first_value_of(p.json, "smoothed_share"), lambda, 0.1 * lambda) << p.json.substr(0, 3000);
}

// A thermal growth of -248 urad/degC from 26.1 degC (just past the plausible 200) under resonant
// AR(2) noise, 15,402 rows at 55.9 Hz while the oil warms 29-48 degC (power table seed 20261241,
// draw 2). g (theta - theta_0) has a curved valley along g theta_0; the descent, its derivative
// taken at a step that follows the moment sums' sawtooth, stopped at -108 urad/degC and an
// assembly misalignment (-39 % held out, against -38 %) was named first. The descent again with a
// coarser derivative (effect_fit.cc, descend_with_coarser_derivative) names the growth first.
TEST(NoiseZooPower, AThermalGrowthIsFollowedAlongItsCurvedValley) {
  const PowerDraw p = diagnosed_power_draw(20261241, 2, "thermal_misalignment");
  ASSERT_NE(p.draw.description.find("growth -0.000248"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, "thermal_misalignment"));
  EXPECT_LT(first_value_of(p.json, "growth_rad_per_c"), -150e-6) << p.json.substr(0, 3000);
}

// A thermal growth of 7.4 urad/degC from 34.0 degC at 1.83 rad under torque-heteroscedastic noise
// and proximity-probe noise carried through the model, 14,304 rows at 10.5 Hz while the oil warms
// 41-50 degC (power table seed 20261287, draw 1). The fit stopped at a reference inside the
// recorded span, 44 degC (1,088 N·m rms on all rows against 872 at the truth), and an assembly
// misalignment was named first. The reference is profiled (ParameterSpec::profiled, effect_fit.cc): the growth
// is named, its reference below the recorded temperatures.
TEST(NoiseZooPower, AThermalGrowthFromBelowTheRecordedTemperaturesIsNamedFirst) {
  const PowerDraw p = diagnosed_power_draw(20261287, 1, "thermal_misalignment");
  ASSERT_NE(p.draw.description.find("growth 7.39e-06 rad/degC from 34.0 degC"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, "thermal_misalignment"));
  EXPECT_LT(first_value_of(p.json, "reference_temperature_c"), 41.0) << p.json.substr(0, 3000);
}

// A spacing error at the library's physical bound, 100 um, scaled x1.40 to reach SNR 1.5, on the
// same recording (seed 20261241, draw 2). Inside the plausible 0-50 um the fit found a valley at
// 42 um, and a torque calibration with a curvature four times its plausible range was named
// first. Scanned beyond the plausible box (scan_beyond_plausible), the spacing error sits on its
// bound; a formula does a little better, but the effect takes most of what it finds, so it is
// claimed as partly explaining (physics first), with the formula shown as the next round's lead.
// (Its T zeta on M_sy', at t = 1.7, shares its error with T zeta times the moment: it is kept.)
TEST(NoiseZooPower, ASpacingErrorAtItsBoundIsNamedAsPartlyExplaining) {
  const PowerDraw p = diagnosed_power_draw(20261241, 2, "spacing_errors");
  ASSERT_NE(p.draw.description.find("spacing error 100 um"), std::string::npos) << p.draw.description;
  EXPECT_TRUE(named_first(p, "spacing_errors"));
  EXPECT_NE(p.out.outcomes.find("partly_explained"), std::string::npos) << p.out.outcomes;
  EXPECT_NE(p.json.find("A formula of physical terms does better on held-out data"), std::string::npos)
      << p.json.substr(0, 4000);
  EXPECT_EQ(p.json.find("no formula did better"), std::string::npos) << p.json.substr(0, 4000);
}

}  // namespace
}  // namespace gc::zoo
