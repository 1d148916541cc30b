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
// row drawn from the residual's own fifths, and with their lines (a cycle, a programme that
// repeats) brought down to the continuum about them. Surrogates of the residual itself took a
// real effect's own spectrum for the noise's (a cross-talk of the model's moments, a drag on a
// speed programme); circular surrogates cannot rise as a walk does (a level and a staircase fitted
// 198 of 300 random walks better than all of them); a line kept in a random phase is explained as
// well by a design in phase with it often enough to cost a real hysteresis its claim. A level the
// design moves is judged apart (level_p_value), a step not at all (change_point.h judges it).
// Several candidates are tested at once, Bonferroni over the family and a design's two parts, so
// the chance that such noise gives any claim is at most the level.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Dense>

namespace gc {

/// `count` surrogates of `residual` (rows in time order, one column per moment channel): each
/// channel's periodogram kept but for its lines, the same random phase added to both channels at
/// each frequency (their cross-spectrum kept), each channel's mean zero, end-matched with a rise
/// of its own drawn from `rise_variance` per channel [N²·m²] (by default the residual's own,
/// rise_variance()).
std::vector<Eigen::MatrixX2d> phase_randomised_surrogates(const Eigen::MatrixX2d& residual, int count,
                                                          std::uint64_t seed,
                                                          std::optional<Eigen::Array2d> rise_variance = std::nullopt);

/// A candidate's design on the rows: columns stacked as the residual is (rows k for M_sy', n + k for
/// M_sz'). `choose` 0: every column; k > 0: the k columns forward selection takes (orthogonal
/// matching pursuit on normalised columns), on the residual and on each surrogate alike.
struct SurrogateDesign {
  Eigen::MatrixXd columns;  ///< 2n x p [N·m per unit of each column's coefficient]
  int choose = 0;
  /// The design moves a channel's level too (an offset, a constant term): judged by level_p_value
  /// beside what it explains of the variation.
  bool level = false;
};

/// The p-value that a channel's level (the mean of `residual`) is no more than its wander: against
/// the spread of the means of 21 contiguous blocks of `wander` (what a design that moves the level
/// leaves, so that structure it explains is not taken for wander), as Student's t with 20 degrees of freedom, the smaller of the
/// two channels' doubled. Not the mean's standard error: a walk's fifths wander together, and
/// its mean is as far from zero as they wander (a random walk's level is no offset); an offset of
/// a calibration stands far out of any noise's fifths.
double level_p_value(const Eigen::MatrixX2d& residual, const Eigen::MatrixX2d& wander);

/// Per design, the p-value that noise with the residual's spectrum is explained as well, times the
/// number of designs and by 2 (Bonferroni over the family and a design's two parts: what it explains
/// of the variation about the levels, by the surrogates, and a level it moves, by level_p_value): (1 + surrogates
/// explained at least as well) / (1 + surrogates drawn). Enough surrogates are drawn for a p-value
/// of half `level`, fewer once the p-value is sure to be above it (Besag and Clifford, 1991).
std::vector<double> surrogate_p_values(const Eigen::MatrixX2d& residual, const std::vector<SurrogateDesign>& designs,
                                       double level, std::uint64_t seed);

}  // namespace gc
