// The noise zoo through the CLI (tests/diagnosis/zoo/): a FIXED sample of 50 noise-only draws
// (master seed 20250601), each diagnosed as a user runs it with the model the recording was made
// from. Any claim is false; the test asserts none. Rows are capped at 60,000 for CI time (the
// full range, up to 200,000 rows, is gc_noise_zoo's). Diagnose's time is driven by whether it
// searches, not by rows: on draws it calls noise it takes 0.4-14 s (174,791 rows: 13.6 s), on
// draws where it claims 37-100 s at -j 1. With today's claim rate the 50 draws take some 15-20
// minutes (hence TIMEOUT 1800); with no claims, a few minutes.
// Two draws at a time, diagnose -j 1 each.
// A failure names every claimed draw: rerun it alone with
//   gc_noise_zoo --gearcoupling build/clients/cli/gearcoupling --seed 20250601 --max-rows 60000 --only K
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "tests/diagnosis/zoo/harness.h"
#include "tests/diagnosis/zoo/zoo.h"

namespace gc::zoo {
namespace {

constexpr std::uint64_t kMasterSeed = 20250601;
constexpr std::size_t kDraws = 50;
constexpr std::size_t kMaxRows = 60000;

TEST(NoiseZoo, FiftyNoiseOnlyDrawsClaimNothing) {
  DrawLimits lim;
  lim.max_rows = kMaxRows;
  const auto root = std::filesystem::temp_directory_path() / ("gc_zoo_test_" + std::to_string(::getpid()));
  std::vector<ZooDraw> draws(kDraws);
  std::vector<DiagnoseOutcome> outcomes(kDraws);
  std::atomic<std::size_t> next{0};
  std::mutex print;
  auto worker = [&]() {
    for (std::size_t k; (k = next++) < kDraws;) {
      ZooDraw d = draw(draw_seed(kMasterSeed, k), lim);
      const auto dir = root / ("draw_" + std::to_string(k));
      const auto model = write_choice(d.model, dir);
      std::ofstream(dir / "recording.csv", std::ios::binary) << d.csv;
      d.csv.clear();
      outcomes[k] = run_diagnose(GC_GEARCOUPLING_PATH, dir / "recording.csv", model, 1);
      draws[k] = std::move(d);
      if (!std::getenv("GC_ZOO_KEEP")) std::filesystem::remove_all(dir);
      std::lock_guard lock(print);
      std::printf("[%zu] %s %s (%.1f s) %s\n", k, outcomes[k].error ? "ERROR" : outcomes[k].claim ? "CLAIM" : "noise",
                  outcomes[k].outcomes.c_str(), outcomes[k].wall_s, draws[k].description.c_str());
      std::fflush(stdout);
    }
  };
  std::thread a(worker), b(worker);
  a.join();
  b.join();
  if (!std::getenv("GC_ZOO_KEEP")) std::filesystem::remove_all(root);

  std::size_t claims = 0, errors = 0;
  std::string report;
  for (std::size_t k = 0; k < kDraws; ++k) {
    const DiagnoseOutcome& o = outcomes[k];
    if (o.error) {
      ++errors;
      report += "  K=" + std::to_string(k) + " ERROR exit " + std::to_string(o.exit_code) + ": " + o.stderr_tail + "\n    " +
                draws[k].description + "\n";
    }
    if (!o.claim) continue;
    ++claims;
    std::string names;
    for (const auto& c : o.claimed) names += (names.empty() ? "" : ", ") + c;
    report += "  K=" + std::to_string(k) + " " + draws[k].description + "\n    outcomes: " + o.outcomes +
              "\n    claimed: " + (names.empty() ? "(none named)" : names) + "\n    numbers: " + o.numbers + "\n";
  }
  std::printf("noise zoo: %zu false claims and %zu errors in %zu draws (master seed %llu; 95 %% upper bound %.1f %%)\n",
              claims, errors, kDraws, static_cast<unsigned long long>(kMasterSeed),
              100 * clopper_pearson_upper(claims, kDraws - errors));
  // The target is 0 (issue 37). This sample measured 5 claims and 1 error (draw 40: the data-quality
  // stage excluded all but 358 of 9,768 rows of white noise on an ADC step as large as the noise)
  // with the claim rule's surrogate test (10 before it): a ratchet with slack for a borderline draw
  // on another machine's floats, which fails on anything clearly worse; not the goal.
  constexpr std::size_t kMostClaimsToday = 8;
  constexpr std::size_t kMostErrorsToday = 1;
  EXPECT_LE(claims, kMostClaimsToday) << "diagnose claimed physics on " << claims << " of " << kDraws
                        << " noise-only recordings (the truth is exactly the model it was given):\n" << report;
  EXPECT_LE(errors, kMostErrorsToday) << report;
}

}  // namespace
}  // namespace gc::zoo
