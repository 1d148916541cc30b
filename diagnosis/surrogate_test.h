// The claim rule's test against noise of the residual's own spectrum: phase-randomised surrogates
// (Theiler, Eubank, Longtin, Galdrikian and Farmer, "Testing for nonlinearity in time series: the
// method of surrogate data", Physica D 58, 1992). A surrogate keeps the residual's periodogram, so
// its correlation at every lag and its slow power, and draws new phases, so it has no relation to
// the inputs. A candidate that explains as much of a surrogate as of the residual explains noise
// that is as slow as this recording's: a random walk projected on a slowly rising temperature is
// the textbook spurious regression (Granger and Newbold, 1974), and interleaved cross-validation
// cannot see it, since every held-out block has fitted neighbours.
//
// The statistic is the same on the residual and on every surrogate: the share of what varies about
// each channel's level that least squares on the candidate's design removes. An effect's design is
// its correction at the fit and its Jacobian there (the directions it can move in); a formula's is
// the catalogue, of which the same number of terms is chosen greedily on each surrogate as on the
// residual (the search's selection is part of the null). The surrogates are of what the candidate
// leaves (the null: the residual is noise like that), end-matched, with a rise from first to last
// row that the noise would have (the leftover's; the residual's own where formula terms of several
// time profiles were chosen for it), and with their lines (a cycle, a programme that repeats)
// brought down to the continuum about them; a resonance of the noise, as broad as its
// neighbouring bins, is no line and is kept. Surrogates of the residual itself took a
// real effect's own spectrum for the noise's (a cross-talk of the model's moments, a drag on a
// speed programme); circular surrogates cannot rise as a walk does (a level and a staircase fitted
// 198 of 300 random walks better than all of them); a line kept in a random phase is explained as
// well by a design in phase with it often enough to cost a real hysteresis its claim. A level the
// design moves is judged apart (level_p_value), a step not at all (change_point.h judges it).
// Where the residual is correlated, the same surrogates can judge a second statistic: the share on
// everything prewhitened by the residual's autoregression (prewhitening.h), least squares made
// generalised for that noise. Under a random walk a torque step's effect is a jump among small
// increments; as a share of what varies, the walk's own wander fits the design as well (an
// assembly misalignment cutting 41 % of the held-out error under brown noise had p = 1 in a
// family of 15, zoo power seed 20261316 draw 5). Where the null is a walk, the share as it is has
// no calibrated null (a stationary surrogate is no walk) and the filtered share judges alone, or,
// where the input sensors' noise would show in it, both must pass; elsewhere the filtered share
// stands beside the share as it is where the inputs are clean (surrogate_test.cc, statistics_for).
// Several candidates are tested at once, Bonferroni over the family, a design's two parts and
// its two statistics where either may claim, so the chance that such noise gives any claim is at
// most the level.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "diagnosis/parallel_for.h"
#include "diagnosis/prewhitening.h"

namespace gc {

/// What a surrogate's spectrum is given beside the periodogram of the series it is drawn from.
struct SurrogateSpectrum {
  /// The variance of the rise from first to last row, per channel [N²·m²]; by default the series'
  /// own (from its first and last fifths).
  std::optional<Eigen::Array2d> rise_variance;
  /// Per channel, the share of each frequency's power (k = 0..m/2 of the FFT's m points, see
  /// leverage) that a least-squares projection removed from the series: given back,
  /// |X(k)| / sqrt(1 - removed(k)), at most kMostRestored of it. Empty: none.
  std::array<std::vector<double>, 2> removed;

  /// Restored up to this share removed (ten times the power at most): where a design spans a
  /// frequency whole, what is left there says nothing of the noise.
  static constexpr double kMostRestored = 0.9;

  /// The leverage of orthonormal `basis` (2n rows, stacked as the channels) at each frequency of
  /// `channel`'s FFT: lev(k) = sum_j |Q_j(k)|^2 / m over the basis columns' transforms, the share
  /// of a unit sinusoid of that frequency in random phase that projecting on the basis takes.
  /// Summed over both halves of the spectrum it is the channel's part of the basis' trace (Parseval). For white noise the
  /// leftover's expected power is (1 - lev(k)) times the noise's.
  static std::vector<double> leverage(const Eigen::MatrixXd& basis, Eigen::Index n, int channel);
};

/// Phase-randomised surrogates of a residual, one at a time (a test that stops early draws no more).
/// Each: `residual`'s periodogram per channel (restored by `shape.removed`) but for its lines, the
/// same random phase added to both channels at each frequency (their cross-spectrum kept), each
/// channel's mean zero, end-matched with a rise of its own drawn from `shape.rise_variance`.
class SurrogateSource {
 public:
  SurrogateSource(const Eigen::MatrixX2d& residual, std::uint64_t seed, const SurrogateSpectrum& shape = {});
  ~SurrogateSource();
  Eigen::MatrixX2d next();

  /// The random numbers of the next surrogate, drawn in order: next() is made(draw()), and
  /// surrogates drawn one after the other can be made on several threads, the same numbers.
  struct Draw {
    std::vector<double> phases;      ///< per frequency k = 1..m/2 [rad]
    std::array<double, 2> rises{};   ///< per channel, standard normal
  };
  Draw draw();
  /// What made() transforms with: one a thread.
  class Workspace {
   public:
    Workspace();
    ~Workspace();
    Workspace(Workspace&&) noexcept;

   private:
    friend class SurrogateSource;
    struct Transform;  // Eigen's FFT, kept out of the installed header (its module is unsupported/)
    std::unique_ptr<Transform> fft_;
  };
  Eigen::MatrixX2d made(const Draw& draw, Workspace& workspace) const;

 private:
  Eigen::Index n_, m_;  ///< rows; the FFT's length (the last m_ rows, wrapped to n_)
  std::mt19937_64 random_;
  Workspace workspace_;  ///< next()'s
  std::array<std::vector<double>, 2> amplitudes_;  ///< per channel, k = 0..m_/2
  std::array<double, 2> rise_sigma_{};             ///< per channel [N·m]
};

/// `count` surrogates of `residual` (rows in time order, one column per moment channel): each
/// channel's periodogram kept (restored by `shape.removed`) but for its lines, the same random
/// phase added to both channels at each frequency (their cross-spectrum kept), each channel's
/// mean zero, end-matched with a rise of its own drawn from `shape.rise_variance` per channel.
std::vector<Eigen::MatrixX2d> phase_randomised_surrogates(const Eigen::MatrixX2d& residual, int count,
                                                          std::uint64_t seed, const SurrogateSpectrum& shape = {});

/// A candidate's design on the rows: columns stacked as the residual is (rows k for M_sy', n + k for
/// M_sz'). `choose` 0: every column; k > 0: the k columns forward selection takes (orthogonal
/// matching pursuit on normalised columns), on the residual and on each surrogate alike.
struct SurrogateDesign {
  Eigen::MatrixXd columns;  ///< 2n x p [N·m per unit of each column's coefficient]
  int choose = 0;
  /// The design moves a channel's level too (an offset, a constant term): judged by level_p_value
  /// beside what it explains of the variation.
  bool level = false;
  /// The same candidate's designs elsewhere in its search box (choose 0): the statistic is the
  /// largest share any of them and `columns` explain, on the residual and on every surrogate alike.
  /// A parameter that only the candidate's presence gives a meaning (a reference temperature, a
  /// direction, a delay) was searched over its box on this residual; a null that looks only where
  /// the search ended is not searched as the residual was (Davies, Biometrika 74, 1987).
  std::vector<Eigen::MatrixXd> elsewhere;
  /// The null drawn from the residual itself, its spectrum as it is, not from what the design
  /// leaves: for a design of many columns along the programme (the signature's bins), which can
  /// take nearly all of a random walk's slow power, so that what it leaves has too little of it to
  /// give back (SurrogateSpectrum::kMostRestored).
  bool null_of_the_residual = false;
  /// The level judged against the residual's own wander, not against what the design leaves: the
  /// design's columns were chosen for this residual among many (a formula's terms), and slow ones
  /// chosen take the very wander the level is judged against.
  bool level_against_the_residual = false;
  /// The time profiles (time_profiles) of the terms the candidate claims, where the design is
  /// chosen again (`choose` > 0): the null's rise is judged by them (surrogate_test.cc,
  /// rise_of_the_noise), not by the terms the greedy choice takes on the residual, which can be
  /// others. Empty: by the greedy choice's.
  std::optional<int> own_profiles = std::nullopt;
};

/// How many distinct time profiles `columns` (2n rows, stacked as the channels) follow, each
/// channel's level aside: the rank of their channels' parts as series of n rows, each part less
/// its mean and at unit scale (a speed term on M_sy' and one on M_sz' follow one profile; a
/// channel's constant follows none; a part under a millionth of its column's squares is none),
/// eigenvalues of their Gram matrix under a hundredth of the largest taken as none.
int time_profiles(const Eigen::MatrixXd& columns, Eigen::Index n);

/// The standard error of a level from the means of contiguous blocks of what wanders about it:
/// the means' spread over sqrt(m), times the inflation (1 + rho) / (1 - rho) (square-rooted) of
/// means correlated as an AR(1) of rho, with rho a one-sided 1 % upper bound on the adjacent means'
/// correlation (its estimate, its small-sample bias and 2.33 standard errors); never more than the
/// spread itself. Means that wander together (a walk, a zero drifting over the whole recording:
/// adjacent ones correlated, rho near 1) give the spread: a walk's mean is as far from zero as its
/// blocks wander, and a random walk's level is no offset. Means nearly independent (a noise whose
/// correlation is shorter than a block) give about 0.39 of the spread for 21 (1.7 / sqrt(21)):
/// in a family of 15 a level must stand about 1.8 spreads out, where the spread alone asked for
/// 4.6 (Student's t at 0.01 / 60, 20 degrees of freedom). A heavier hub's offset of 4.7 kN·m, 44 %
/// of the held-out error at t = 21, under an AR(1) whose correlation was shorter than a block, was
/// no claim with the spread (p = 0.033 in the family; zoo power seed 20261263, draw 7).
double level_standard_error(const Eigen::VectorXd& means);

/// The p-value that a channel's level (the mean of `residual`) is no more than its wander: against
/// level_standard_error of the means of 21 contiguous blocks of `wander` (what a design that moves
/// the level leaves, so that structure it explains is not taken for wander), as Student's t with 20
/// degrees of freedom, the smaller of the two channels' doubled.
double level_p_value(const Eigen::MatrixX2d& residual, const Eigen::MatrixX2d& wander);

/// The test's statistic: the share of what varies about each channel's level of `residual` (rows
/// in time order, one column per moment channel) that `design` explains beyond the levels, its
/// `choose` columns selected forward on this residual where choose > 0; the largest of it and of
/// its designs `elsewhere`.
double explained_share(const Eigen::MatrixX2d& residual, const SurrogateDesign& design);

/// Per design, the p-value that noise with the residual's spectrum is explained as well, times the
/// family's size and by 2 (Bonferroni over the family and a design's two parts: what it explains
/// of the variation about the levels, by the surrogates, and a level it moves, by level_p_value),
/// and by 2 again where both the share as it is and the filtered one judge it and either may claim
/// (the smaller p-value of the two; the larger where both must pass): (1 + surrogates
/// explained at least as well) / (1 + surrogates drawn). Enough surrogates are drawn for a p-value
/// of half `level`, fewer once the p-value is sure to be above it (Besag and Clifford, 1991), or
/// once the first 199, none explained as well, put a bound on its tail below half the level
/// (Cantelli's, or ten times the Beta of their moments).
///
/// `family_size`: how many candidates the search tried (at least the designs): the designs tested
/// are those that passed the claim rule's other tests on the same residual, so the one that fits
/// noise best among all tried is among them, and the correction must count every one tried.
///
/// The surrogates are drawn in order, a few at a time, and their shares found over `parallel`,
/// then taken in order: the p-values do not depend on the threads.
///
/// `prewhitening`: the filter of the second statistic (Prewhitening::fitted of the residual),
/// marked where the inputs' noise would show in it (exposes_input_noise).
std::vector<double> surrogate_p_values(const Eigen::MatrixX2d& residual, const std::vector<SurrogateDesign>& designs,
                                       double level, std::uint64_t seed, std::size_t family_size,
                                       const ParallelFor& parallel, const Prewhitening& prewhitening);

/// The same with no filter: the shares as they are alone. (An overload, not a default argument:
/// clang 14 does not emit Eigen's inline constructors for a `= {}` aggregate default in a caller's
/// translation unit, and the library would not link under the fuzz build.)
std::vector<double> surrogate_p_values(const Eigen::MatrixX2d& residual, const std::vector<SurrogateDesign>& designs,
                                       double level, std::uint64_t seed, std::size_t family_size = 0,
                                       const ParallelFor& parallel = serial_for());

}  // namespace gc
