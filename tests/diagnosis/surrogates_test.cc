// The surrogate test of the claim rule (diagnosis/surrogate_test.h), measured as a rate on
// fresh draws: its size on slow noise that no input explains, its power on a small real term.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "diagnosis/surrogate_test.h"

namespace gc {
namespace {

constexpr int kRows = 600;

// Fewer draws in unoptimised builds (the sanitizer runs of tests/run_all.sh), where Eigen is tens
// of times slower; the rates are measured in the optimised build.
#ifdef NDEBUG
constexpr int kScale = 1;
#else
constexpr int kScale = 10;
#endif

/// Both channels a random walk (brown noise) of unit steps.
Eigen::MatrixX2d random_walk(std::mt19937_64& random) {
  std::normal_distribution<double> step;
  Eigen::MatrixX2d out(kRows, 2);
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  for (int i = 0; i < kRows; ++i) {
    at += Eigen::Vector2d(step(random), step(random));
    out.row(i) = at.transpose();
  }
  return out;
}

/// surrogate_p_values as the diagnosis calls it on a recording with clean inputs: one design, the
/// 1 % level, and the residual's own prewhitening filter.
double p_value(const Eigen::MatrixX2d& y, const SurrogateDesign& design, std::uint64_t seed) {
  return surrogate_p_values(y, {design}, 0.01, seed, 0, serial_for(), Prewhitening::fitted(y))[0];
}

/// A level and a slow staircase on each channel: what a gain and an offset fit on a load staircase.
SurrogateDesign offset_and_staircase() {
  Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(2 * kRows, 4);
  for (int i = 0; i < kRows; ++i) {
    const double stair = std::floor(4.0 * i / kRows);
    columns(i, 0) = 1.0;
    columns(i, 1) = stair;
    columns(kRows + i, 2) = 1.0;
    columns(kRows + i, 3) = stair;
  }
  return {columns, 0, false, {}};
}

// A surrogate keeps the noise's power away from the lowest frequencies, but not a line.
TEST(Surrogates, KeepTheNoisesPowerButNotALine) {
  std::mt19937_64 random(11);
  std::normal_distribution<double> white;
  Eigen::MatrixX2d x(kRows, 2);
  for (int i = 0; i < kRows; ++i) x.row(i) << white(random) + 3.0 * std::cos(2.0 * std::numbers::pi * 50.0 * i / kRows), white(random);
  const std::vector<Eigen::MatrixX2d> s = phase_randomised_surrogates(x, 3, 5);
  ASSERT_EQ(s.size(), 3u);
  Eigen::FFT<double> fft;
  for (int c = 0; c < 2; ++c) {
    std::vector<std::complex<double>> a, b;
    fft.fwd(a, std::vector<double>(x.col(c).data(), x.col(c).data() + kRows));
    fft.fwd(b, std::vector<double>(s[1].col(c).data(), s[1].col(c).data() + kRows));
    double band_a = 0.0, band_b = 0.0;
    for (int k = 10; k < kRows / 2; ++k) {
      if (std::abs(k - 50) <= 1) continue;
      band_a += std::norm(a[k]);
      band_b += std::norm(b[k]);
    }
    EXPECT_NEAR(band_b / band_a, 1.0, 0.05) << "channel " << c;
    if (c == 0) {
      EXPECT_LT(std::abs(b[50]), 0.2 * std::abs(a[50])) << "the line at bin 50 is kept";
    }
  }
}

// A resonance of the noise is broad, not a line: a surrogate keeps its power (an AR(2) peak brought
// down as a line left surrogates without it, and a cycle at its top was claimed on a noise-only
// recording, zoo seed 20261284 draw 495). r = 0.93 at bin 100 of 600: about 13 bins wide.
TEST(Surrogates, KeepABroadResonanceOfTheNoise) {
  std::mt19937_64 random(12);
  std::normal_distribution<double> white;
  const double r = 0.93, w = 2.0 * std::numbers::pi * 100.0 / kRows;
  Eigen::MatrixX2d x(kRows, 2);
  for (int c = 0; c < 2; ++c) {
    double x1 = 0.0, x2 = 0.0;
    for (int i = -1000; i < kRows; ++i) {
      const double x0 = 2.0 * r * std::cos(w) * x1 - r * r * x2 + white(random);
      x2 = x1;
      x1 = x0;
      if (i >= 0) x(i, c) = x0;
    }
  }
  Eigen::FFT<double> fft;
  const auto peak_power = [&](const Eigen::MatrixX2d& m, int c) {
    std::vector<std::complex<double>> f;
    fft.fwd(f, std::vector<double>(m.col(c).data(), m.col(c).data() + kRows));
    double sum = 0.0;
    for (int k = 97; k <= 103; ++k) sum += std::norm(f[k]);
    return sum;
  };
  const std::vector<Eigen::MatrixX2d> s = phase_randomised_surrogates(x, 8, 5);
  for (int c = 0; c < 2; ++c) {
    double kept = 0.0;
    for (const Eigen::MatrixX2d& one : s) kept += peak_power(one, c) / peak_power(x, c);
    EXPECT_NEAR(kept / static_cast<double>(s.size()), 1.0, 0.25) << "channel " << c;
  }
}

// The size on the hardest noise: 300 fresh random walks, a level and a staircase on each channel
// (the spurious regression that interleaved cross-validation passed). The bound is 2 %, the level
// of 1 % with room for 300 draws' scatter. With circular surrogates of the residual it was 198 of
// 300; with surrogates of the leftover whose rise came from the leftover, 20 of 300; from the
// leftover given back its leverage, 59; from the leftover's blocks extrapolated (white noise and a
// walk), 4 to 6 (measured 2026-11-29; the residual's own rise is kept, docs/diagnosis.md).
TEST(Surrogates, OnRandomWalksASlowDesignIsClaimedAtMostAtTheLevel) {
  std::mt19937_64 random(20261128);
  const SurrogateDesign design = offset_and_staircase();
  int claimed = 0;
  const int draws = 300 / kScale;
  for (int d = 0; d < draws; ++d) {
    const Eigen::MatrixX2d noise = random_walk(random);
    if (p_value(noise, design, random()) <= 0.01) ++claimed;
  }
  std::printf("a level and a staircase on random walks: claimed in %d of %d draws\n", claimed, draws);
  EXPECT_LE(claimed, std::max(2, draws * 2 / 100)) << claimed << " of " << draws;
}

// The power under a random walk: the staircase of offset_and_staircase at steps of 6 walk steps
// on M_sz' alone, a torque staircase's effect, is found in at least 90 % of 100 fresh draws. As
// a share of what varies, the walk explains itself as well as the steps do (the surrogates fit a
// staircase about as well); prewhitened, each step is a jump of 6 sigma among unit steps. Without
// the prewhitened statistic it was found in 5 of 100, with it 99 (measured 2026-12-02); the size
// tests on walks and wandering zeros claimed 4, 2 and 2 of 300 before it and 1, 1 and 1 with it.
TEST(Surrogates, FindsAStaircaseUnderARandomWalkByItsSteps) {
  std::mt19937_64 random(20261320);
  const SurrogateDesign design = offset_and_staircase();
  int found = 0;
  const int draws = 100 / kScale;
  for (int d = 0; d < draws; ++d) {
    Eigen::MatrixX2d y = random_walk(random);
    for (int i = 0; i < kRows; ++i) y(i, 1) += 6.0 * design.columns(kRows + i, 3);
    if (p_value(y, design, random()) <= 0.01) ++found;
  }
  std::printf("a staircase of 6 walk steps under a random walk: found in %d of %d draws\n", found, draws);
  EXPECT_GE(found, draws * 90 / 100) << found << " of " << draws;
}

// The power: a term that follows a slow input programme (a speed staircase with ramps, as a drag
// does) at 0.6 noise sigma in white noise, found in at least 95 % of 100 draws (at 0.4 sigma, 60). A cycle at a fixed
// frequency is not judged here: a surrogate keeps its spectral line (cycle_period.h tests it).
TEST(Surrogates, FindsASmallTermThatFollowsASlowInput) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> white;
  Eigen::MatrixXd programme = Eigen::MatrixXd::Zero(2 * kRows, 1);
  for (int i = 0; i < kRows; ++i) programme(kRows + i, 0) = std::min(1.0, std::fmod(5.0 * i / kRows, 1.0) * 3.0) - 0.5;
  programme.col(0) /= programme.col(0).norm() / std::sqrt(static_cast<double>(kRows));
  int found = 0;
  const int draws = 100 / kScale;
  for (int d = 0; d < draws; ++d) {
    Eigen::MatrixX2d y(kRows, 2);
    for (int i = 0; i < kRows; ++i) y.row(i) << white(random), white(random) + 0.6 * programme(kRows + i, 0);
    if (p_value(y, {programme, 0, false, {}}, random()) <= 0.01) ++found;
  }
  EXPECT_GE(found, draws * 95 / 100) << found << " of " << draws;
}

// A family: the p-values are multiplied by its size, and enough surrogates are drawn for it.
TEST(Surrogates, AFamilyOfDesignsIsAdjustedForItsSize) {
  std::mt19937_64 random(3);
  std::normal_distribution<double> white;
  Eigen::MatrixX2d y(kRows, 2);
  for (int i = 0; i < kRows; ++i) y.row(i) << white(random) + 3.0 * std::cos(i / 10.0), white(random);
  Eigen::MatrixXd strong = Eigen::MatrixXd::Zero(2 * kRows, 1);
  for (int i = 0; i < kRows; ++i) strong(i, 0) = std::cos(i / 10.0);
  const std::vector<SurrogateDesign> family(8, SurrogateDesign{strong, 0, false, {}});
  const std::vector<double> p = surrogate_p_values(y, family, 0.01, 1);
  for (double v : p) EXPECT_LE(v, 0.01);
  // One design tested out of a family of 8 tried is adjusted as much as each of 8 tested.
  EXPECT_DOUBLE_EQ(surrogate_p_values(y, {family[0]}, 0.01, 1, 8)[0], p[0]);
  // A weak design's p-value counts the family: 8 times the one tested alone, up to 1.
  Eigen::MatrixXd weak = Eigen::MatrixXd::Zero(2 * kRows, 1);
  for (int i = 0; i < kRows; ++i) weak(kRows + i, 0) = std::sin(i / 7.0);
  const double alone = surrogate_p_values(y, {{weak, 0, false, {}}}, 0.01, 1)[0];
  EXPECT_NEAR(surrogate_p_values(y, {{weak, 0, false, {}}}, 0.01, 1, 8)[0], std::min(1.0, 8 * alone), 0.2);
}

// The surrogates' shares are found side by side and taken in order: however the work is shared,
// each p-value is the same to the bit. Here one half of a batch a call, last first; a weak design
// draws every surrogate, a strong one stops after the first 199 on their tail.
TEST(Surrogates, PValuesDoNotDependOnHowTheSharesAreShared) {
  std::mt19937_64 random(11);
  std::normal_distribution<double> white;
  Eigen::MatrixX2d y(kRows, 2);
  for (int i = 0; i < kRows; ++i) y.row(i) << white(random) + 0.5 * std::cos(i / 10.0), white(random);
  Eigen::MatrixXd strong = Eigen::MatrixXd::Zero(2 * kRows, 1), weak = Eigen::MatrixXd::Zero(2 * kRows, 1);
  for (int i = 0; i < kRows; ++i) {
    strong(i, 0) = std::cos(i / 10.0);
    weak(kRows + i, 0) = std::sin(i / 7.0);
  }
  const ParallelFor backwards = [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
    for (std::size_t i = count; i-- > 0;) body(i, i + 1);
  };
  const std::vector<SurrogateDesign> designs = {{strong, 0, false, {}}, {weak, 0, false, {}}};
  const std::vector<double> serial = surrogate_p_values(y, designs, 0.01, 5);
  const std::vector<double> shared = surrogate_p_values(y, designs, 0.01, 5, 0, backwards);
  ASSERT_EQ(serial.size(), 2u);
  EXPECT_LE(serial[0], 0.01);
  EXPECT_GT(serial[1], 0.01);
  EXPECT_EQ(shared[0], serial[0]);
  EXPECT_EQ(shared[1], serial[1]);
}

// A surrogate made from its random numbers (SurrogateSource::draw, made) is next()'s to the bit,
// whichever thread makes it with whichever workspace, and in whatever order: the p-values' batches
// are made on two threads from numbers drawn in order.
TEST(Surrogates, MadeFromTheirNumbersAreNextsToTheBit) {
  std::mt19937_64 random(17);
  std::normal_distribution<double> white;
  Eigen::MatrixX2d y(kRows, 2);
  double walk = 0.0;
  for (int i = 0; i < kRows; ++i) y.row(i) << (walk += white(random)), white(random) + 0.3 * walk;
  SurrogateSource one_by_one(y, 23), by_numbers(y, 23);
  std::vector<Eigen::MatrixX2d> expected;
  std::vector<SurrogateSource::Draw> numbers;
  for (int k = 0; k < 5; ++k) {
    expected.push_back(one_by_one.next());
    numbers.push_back(by_numbers.draw());
  }
  std::array<SurrogateSource::Workspace, 2> workspaces;
  for (int k = 4; k >= 0; --k) {
    const Eigen::MatrixX2d made = by_numbers.made(numbers[static_cast<std::size_t>(k)], workspaces[static_cast<std::size_t>(k % 2)]);
    EXPECT_EQ((made - expected[static_cast<std::size_t>(k)]).cwiseAbs().maxCoeff(), 0.0) << "surrogate " << k;
  }
  EXPECT_GT((expected[0] - expected[1]).cwiseAbs().maxCoeff(), 0.0);
}

/// A bump on channel y centred at `at` of the rows, 3 % of them wide: a correction that one
/// parameter places (a reference temperature, a torque, a time), each place nearly apart from the next.
Eigen::MatrixXd bump(double at) {
  Eigen::MatrixXd column = Eigen::MatrixXd::Zero(2 * kRows, 1);
  for (int i = 0; i < kRows; ++i) column(i, 0) = std::exp(-0.5 * std::pow((static_cast<double>(i) / kRows - at) / 0.03, 2));
  return column;
}

// Davies' problem: a parameter that only the candidate gives a meaning (where its bump sits)
// was searched on the residual, so the design at the fit is the best of many. Judged where the
// search ended, the surrogate test is liberal; with the box scanned on every surrogate too
// (SurrogateDesign::elsewhere) it comes near its size. 300 fresh draws of AR(1) noise (phi 0.5),
// the bump's place searched over 24 places, all of them scanned: measured 63 of 300 at the fit, 8
// scanned (2.7 %, for a level of 1 %: the leftover lacks the noise the chosen bump took, more than
// its leverage says, since it was chosen for taking the most).
TEST(Surrogates, ASearchedParameterIsSearchedOnTheSurrogatesToo) {
  std::mt19937_64 random(20261129);
  std::normal_distribution<double> white;
  std::vector<Eigen::MatrixXd> places;
  for (int k = 0; k < 24; ++k) places.push_back(bump((k + 0.5) / 24.0));
  int claimed_at_fit = 0, claimed_scanned = 0;
  const int draws = 300 / kScale;
  for (int d = 0; d < draws; ++d) {
    Eigen::MatrixX2d noise(kRows, 2);
    Eigen::Vector2d at = Eigen::Vector2d::Zero();
    for (int i = 0; i < kRows; ++i) {
      at = 0.5 * at + Eigen::Vector2d(white(random), white(random));
      noise.row(i) = at.transpose();
    }
    // The search: the place whose bump explains most of the residual's variation.
    std::size_t best = 0;
    double best_share = -1.0;
    const Eigen::VectorXd y = noise.col(0).array() - noise.col(0).mean();
    for (std::size_t k = 0; k < places.size(); ++k) {
      const Eigen::VectorXd x = places[k].col(0).head(kRows).array() - places[k].col(0).head(kRows).mean();
      const double share = std::pow(x.dot(y), 2) / (x.squaredNorm() * y.squaredNorm());
      if (share > best_share) best_share = share, best = k;
    }
    const std::uint64_t seed = random();
    if (p_value(noise, {places[best], 0, false, {}}, seed) <= 0.01) ++claimed_at_fit;
    if (p_value(noise, {places[best], 0, false, places}, seed) <= 0.01) ++claimed_scanned;
  }
  std::printf("a searched bump in AR(1) noise: claimed in %d of %d draws judged at the fit, %d scanned\n",
              claimed_at_fit, draws, claimed_scanned);
  EXPECT_LE(claimed_scanned, std::max(3, draws * 3 / 100)) << claimed_scanned << " of " << draws;
  // What the scan is for: judged only where the search ended, the hinge is claimed more often
  // (measured in the optimised build, with all the draws).
  if (kScale == 1) {
    EXPECT_GE(claimed_at_fit, 4 * claimed_scanned) << claimed_at_fit << " of " << draws;
  }
}

// The power where a term's programme ends elsewhere than it began: three quarters of a slow cycle
// (it rises by 1.3 of its amplitude from the first fifth to the last) at 1.5 times the rms of a
// slow AR(1) noise (phi 0.98) beside white noise, in at least 80 % of 100 fresh draws: measured 92
// with the residual's own rise, which carries the term's; 95 with the rise of the noise the term
// leaves, which was tried and left a false claim on the zoo's CI sample (2026-11-29).
TEST(Surrogates, FindsASlowTermWhoseProgrammeEndsElsewhere) {
  std::mt19937_64 random(20261129);
  std::normal_distribution<double> white;
  Eigen::MatrixXd term = Eigen::MatrixXd::Zero(2 * kRows, 1);
  for (int i = 0; i < kRows; ++i) {
    const double cycle = std::sin(1.5 * std::numbers::pi * i / kRows);
    term(i, 0) = cycle;
    term(kRows + i, 0) = 0.5 * cycle;
  }
  int found = 0;
  const int draws = 100 / kScale;
  for (int d = 0; d < draws; ++d) {
    Eigen::MatrixX2d noise(kRows, 2);
    Eigen::Vector2d slow = Eigen::Vector2d::Zero();
    for (int i = 0; i < kRows; ++i) {
      slow = 0.98 * slow + 0.2 * Eigen::Vector2d(white(random), white(random));
      noise.row(i) = (slow + Eigen::Vector2d(white(random), white(random))).transpose();
    }
    const double scale = 1.5 * std::sqrt(noise.squaredNorm() / (2.0 * kRows)) /
                         std::sqrt(term.col(0).squaredNorm() / (2.0 * kRows));
    const Eigen::MatrixX2d y = noise + scale * Eigen::Map<const Eigen::MatrixX2d>(term.data(), kRows, 2);
    if (p_value(y, {term, 0, false, {}}, random()) <= 0.01) ++found;
  }
  std::printf("a slow term ending elsewhere at 1.5 times slow noise: found in %d of %d draws\n", found, draws);
  EXPECT_GE(found, draws * 80 / 100) << found << " of " << draws;
}

/// A catalogue of slow columns on both channels, as a formula's terms are: `programme`, a slow
/// cycle and a slower one, a time ramp and a staircase, on each; `choose` of them are taken, on the
/// residual and on every surrogate alike.
SurrogateDesign slow_catalogue(const Eigen::VectorXd& programme, int choose) {
  constexpr int per_channel = 5;
  Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(2 * kRows, 2 * per_channel);
  for (int i = 0; i < kRows; ++i) {
    const double t = static_cast<double>(i) / kRows;
    const double terms[] = {programme(i), std::cos(3.0 * std::numbers::pi * t), std::cos(2.0 * std::numbers::pi * t),
                            t, std::floor(4.0 * t)};
    for (int c = 0; c < 2; ++c) {
      for (int j = 0; j < per_channel; ++j) columns(c * kRows + i, per_channel * c + j) = terms[j];
    }
  }
  return {columns, choose, false, {}};
}

/// A speed programme as the zoo's blocks make one: a wandering first part, a hold, a sweep, so that
/// it ends elsewhere than it began without being a ramp [unit RMS].
Eigen::VectorXd programme_ending_elsewhere() {
  Eigen::VectorXd x(kRows);
  for (int i = 0; i < kRows; ++i) {
    const double t = static_cast<double>(i) / kRows;
    x(i) = t < 0.4 ? std::sin(9.0 * std::numbers::pi * t) : t < 0.7 ? 0.3 : 0.3 + 2.0 * (t - 0.7);
  }
  return (x.array() - x.mean()).matrix() / std::sqrt((x.array() - x.mean()).square().mean());
}

// The size where a formula's terms are chosen, two of a catalogue of slow ones (a ramp or a
// staircase is taken on a random walk): the surrogates get the residual's own rise, or the choice,
// which took the walk's rise, would leave a null with none. Claimed at most at the level, 2 % of
// 300 random walks.
TEST(Surrogates, OnRandomWalksChosenSlowTermsAreClaimedAtMostAtTheLevel) {
  std::mt19937_64 random(20261131);
  const SurrogateDesign catalogue = slow_catalogue(programme_ending_elsewhere(), 2);
  int claimed = 0;
  const int draws = 300 / kScale;
  for (int d = 0; d < draws; ++d) {
    if (p_value(random_walk(random), catalogue, random()) <= 0.01) ++claimed;
  }
  std::printf("two slow terms chosen on random walks: claimed in %d of %d draws\n", claimed, draws);
  EXPECT_LE(claimed, std::max(2, draws * 2 / 100)) << claimed << " of " << draws;
}

/// Both channels a wandering zero: an AR(1) whose time constant is `tau` rows, under white noise
/// of `white` times its own RMS [unit RMS before the white].
Eigen::MatrixX2d wandering_zero(std::mt19937_64& random, double tau, double white) {
  std::normal_distribution<double> normal;
  const double phi = std::exp(-1.0 / tau), innovation = std::sqrt(1.0 - phi * phi);
  Eigen::MatrixX2d out(kRows, 2);
  Eigen::Vector2d at(normal(random), normal(random));
  for (int i = 0; i < kRows; ++i) {
    at = phi * at + innovation * Eigen::Vector2d(normal(random), normal(random));
    out.row(i) = (at + white * Eigen::Vector2d(normal(random), normal(random))).transpose();
  }
  return out;
}

// The size where one slow term is chosen on wandering zeros (an AR(1) whose time constant is a
// tenth to a half of the rows, under white noise of 0.6 of its RMS), the zoo's hardest slow noise,
// and judged against the leftover's rise: claimed at most at the level, 2 % of 300 draws. Measured
// 2026-12-01: 2 of 300 (5 with the residual's rise). Two and three slow terms, which keep the
// residual's rise, were claimed in 10 and 17 (docs/diagnosis.md: not fixed).
TEST(Surrogates, OnWanderingZerosOneChosenSlowTermIsClaimedAtMostAtTheLevel) {
  std::mt19937_64 random(20261300);
  const SurrogateDesign catalogue = slow_catalogue(programme_ending_elsewhere(), 1);
  const int draws = 300 / kScale;
  int claimed = 0;
  for (int d = 0; d < draws; ++d) {
    const double tau = kRows * (0.1 + 0.4 * std::uniform_real_distribution<double>()(random));
    if (p_value(wandering_zero(random, tau, 0.6), catalogue, random()) <= 0.01) ++claimed;
  }
  std::printf("one slow term chosen on wandering zeros: claimed in %d of %d draws\n", claimed, draws);
  EXPECT_LE(claimed, std::max(2, draws * 2 / 100)) << claimed << " of " << draws;
}

// The power where terms of one profile are chosen: a term following a programme that ends
// elsewhere than it began (a drag on a speed ramp) in white noise, found in at least 95 of 100 draws
// at 0.5 and at 0.8 of the noise's sigma, on one channel (one term chosen) and between the two (a term on each,
// two chosen). The surrogates' rise is the leftover's, not the residual's, which holds the terms'
// own rise: with it the term on one channel was found in 6 and 3 of 100 at 0.5 and 0.8 sigma, less
// often the stronger it was, and the one between the channels in 15 and 12.
TEST(Surrogates, TermsOfOneProfileThatFollowASlowInputAreFoundInWhiteNoise) {
  std::mt19937_64 random(20261301);
  std::normal_distribution<double> normal;
  const Eigen::VectorXd programme = programme_ending_elsewhere();
  const int draws = 100 / kScale;
  for (const bool between : {false, true}) {
    const SurrogateDesign catalogue = slow_catalogue(programme, between ? 2 : 1);
    for (const double size : {0.5, 0.8}) {
      int found = 0;
      for (int d = 0; d < draws; ++d) {
        const double angle = between ? std::uniform_real_distribution<double>(0.3, 1.2)(random) : std::numbers::pi / 2.0;
        Eigen::MatrixX2d y(kRows, 2);
        for (int i = 0; i < kRows; ++i) {
          y.row(i) << normal(random) + size * std::cos(angle) * programme(i), normal(random) + size * std::sin(angle) * programme(i);
        }
        if (p_value(y, catalogue, random()) <= 0.01) ++found;
      }
      std::printf("a term %s at %.1f sigma in white noise: found in %d of %d draws\n",
                  between ? "between the channels" : "on one channel", size, found, draws);
      EXPECT_GE(found, draws * 95 / 100) << (between ? "between" : "one channel") << ", " << size << " sigma: " << found;
    }
  }
}

// The time profiles a formula's own terms follow (time_profiles), which say which rise its null
// is given: a speed term on each channel is one profile, a speed term and t^3 beside it are two,
// a channel's constant is none, and the other channel's rounding is no part.
TEST(Surrogates, TimeProfilesCountWhatTheTermsFollowTheirLevelsAside) {
  Eigen::MatrixXd speed = Eigen::MatrixXd::Zero(2 * kRows, 2), mixed = speed, constant = Eigen::MatrixXd::Zero(2 * kRows, 1);
  const Eigen::VectorXd programme = programme_ending_elsewhere();
  for (int i = 0; i < kRows; ++i) {
    const double t = static_cast<double>(i) / kRows;
    const double n = 10.0 + programme(i);  // a speed about 10 rpm: mostly a level
    speed(i, 0) = n;
    speed(kRows + i, 1) = n;
    speed(kRows + i, 0) = 1e-9 * n;  // rounding on the other channel
    mixed(i, 0) = n;
    mixed(kRows + i, 1) = t * t * t;
    constant(i, 0) = 1.0;
  }
  EXPECT_EQ(time_profiles(speed, kRows), 1);
  EXPECT_EQ(time_profiles(mixed, kRows), 2);
  EXPECT_EQ(time_profiles(constant, kRows), 0);
  Eigen::MatrixXd with_constant(2 * kRows, 3);
  with_constant << speed, constant;
  EXPECT_EQ(time_profiles(with_constant, kRows), 1);
}

// A level's standard error from 21 block means (level_standard_error). Independent means (white
// noise) give about 1.7 / sqrt(21) of their spread: a level of 2.845 such errors is p = 0.01 at 20
// degrees of freedom, and white noise reaches it in about 0.1 % of draws (the 1 % bound on the
// means' correlation is conservative where there is none). A random walk's means wander together:
// their spread itself, as the level test had for every noise before, and a walk's level stands
// 2.845 errors out in about 2.5 % of draws with either (the rest of the claim rule, the whole
// fifths and the surrogates, keeps walks below the level: OnRandomWalksASlowDesignIs...).
TEST(Surrogates, ALevelIsJudgedOnItsStandardErrorWhereTheBlockMeansAreIndependentAndOnTheirSpreadForAWalk) {
  std::mt19937_64 random(20261201);
  std::normal_distribution<double> normal;
  const int draws = 2000;
  const Eigen::Index blocks = 21, length = 150;
  int white_out = 0, walk_out = 0, walk_spread = 0;
  std::vector<double> white_ratio;
  for (int d = 0; d < draws; ++d) {
    Eigen::VectorXd white(blocks), walk(blocks);
    double position = 0.0;
    for (Eigen::Index k = 0; k < blocks; ++k) {
      double sum = 0.0, walked = 0.0;
      for (Eigen::Index i = 0; i < length; ++i) {
        sum += normal(random);
        walked += (position += normal(random));
      }
      white(k) = sum / length;
      walk(k) = walked / length;
    }
    const auto spread = [&](const Eigen::VectorXd& m) {
      return std::sqrt((m.array() - m.mean()).square().sum() / (blocks - 1.0));
    };
    const double white_error = level_standard_error(white), walk_error = level_standard_error(walk);
    white_ratio.push_back(white_error / spread(white));
    if (std::abs(white.mean()) > 2.845 * white_error) ++white_out;
    if (std::abs(walk.mean()) > 2.845 * walk_error) ++walk_out;
    if (walk_error >= spread(walk) * (1.0 - 1e-12)) ++walk_spread;
  }
  std::nth_element(white_ratio.begin(), white_ratio.begin() + draws / 2, white_ratio.end());
  const double median_ratio = white_ratio[draws / 2];
  std::printf("white: error / spread median %.3f, level out %d of %d; walk: the spread in %d, level out %d\n",
              median_ratio, white_out, draws, walk_spread, walk_out);
  EXPECT_GT(median_ratio, 1.0 / std::sqrt(21.0));   // never below the independent error
  EXPECT_LT(median_ratio, 0.45);                      // far below the spread the test used before
  EXPECT_LE(white_out, draws / 100);                  // at most the 1 % level
  EXPECT_GE(walk_spread, draws * 9 / 10);             // a walk's means: the spread
  EXPECT_LE(walk_out, draws * 4 / 100);               // as before (2.5 %), with room for scatter
}

/// Forward selection as its definition reads (orthogonal matching pursuit): `choose` steps, each
/// taking the unit column, clear of the levels, most correlated with what the levels and the
/// chosen leave; the share of what varies about the levels that the chosen explain.
double selected_share_by_definition(const Eigen::VectorXd& y, const Eigen::MatrixXd& columns, int choose) {
  const Eigen::Index n2 = y.size(), n = n2 / 2;
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(n2, 2);
  basis.col(0).head(n).setConstant(1.0 / std::sqrt(static_cast<double>(n)));
  basis.col(1).tail(n).setConstant(1.0 / std::sqrt(static_cast<double>(n)));
  const auto project = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(basis);
    const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(n2, basis.cols());
    return q * (q.transpose() * v);
  };
  Eigen::MatrixXd unit = columns;
  for (Eigen::Index j = 0; j < unit.cols(); ++j) {
    unit.col(j).head(n).array() -= unit.col(j).head(n).mean();
    unit.col(j).tail(n).array() -= unit.col(j).tail(n).mean();
    unit.col(j).normalize();
  }
  const double level = project(y).squaredNorm();
  std::vector<bool> taken(static_cast<std::size_t>(unit.cols()), false);
  for (int step = 0; step < choose; ++step) {
    const Eigen::VectorXd left = y - project(y);
    Eigen::Index best = -1;
    for (Eigen::Index j = 0; j < unit.cols(); ++j) {
      if (!taken[static_cast<std::size_t>(j)] && (best < 0 || std::abs(unit.col(j).dot(left)) > std::abs(unit.col(best).dot(left)))) best = j;
    }
    taken[static_cast<std::size_t>(best)] = true;
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = unit.col(best);
  }
  return (project(y).squaredNorm() - level) / (y.squaredNorm() - level);
}

// The statistic of a formula's design (choose > 0) is found from the columns' Gram matrix and one
// pass over the rows per residual, not one a step: the same columns chosen, the same share, as the
// selection reads by its definition, on noise (where the choice is a near thing between columns)
// and on two planted terms among correlated ones.
TEST(Surrogates, AFormulasShareIsItsForwardSelectionsProjection) {
  std::mt19937_64 random(20261201);
  std::normal_distribution<double> normal;
  const Eigen::Index n = 300, p = 40;
  Eigen::MatrixXd columns(2 * n, p);
  for (Eigen::Index j = 0; j < p; ++j) {
    for (Eigen::Index i = 0; i < 2 * n; ++i) columns(i, j) = normal(random) + 0.5 * static_cast<double>(j % 3);
  }
  columns.col(p - 1) = columns.col(0) + 0.3 * columns.col(1);  // correlated with the planted ones
  for (const int choose : {1, 2, 5}) {
    for (int draw = 0; draw < 4; ++draw) {
      Eigen::VectorXd y(2 * n);
      for (Eigen::Index i = 0; i < 2 * n; ++i) y(i) = normal(random) + 3.0;
      if (draw % 2 == 1) y += 0.4 * columns.col(0) - 0.3 * columns.col(7);
      Eigen::MatrixX2d residual(n, 2);
      residual.col(0) = y.head(n);
      residual.col(1) = y.tail(n);
      const double share = explained_share(residual, SurrogateDesign{columns, choose, false, {}});
      EXPECT_NEAR(share, selected_share_by_definition(y, columns, choose), 1e-10) << "choose " << choose << ", draw " << draw;
    }
  }
}

}  // namespace
}  // namespace gc
