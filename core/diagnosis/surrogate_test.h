// The claim rule's test against noise of the residual's own spectrum: phase-randomised surrogates
// (Theiler, Eubank, Longtin, Galdrikian and Farmer, "Testing for nonlinearity in time series: the
// method of surrogate data", Physica D 58, 1992). A surrogate keeps the residual's periodogram, so
// its correlation at every lag and its slow power, and draws new phases, so it has no relation to
// the inputs. A candidate that explains as much of a surrogate as of the residual explains noise
// that is as slow as this recording's: a random walk projected on a slowly rising temperature is
// the textbook spurious regression (Granger and Newbold, 1974), and interleaved cross-validation
// cannot see it, since every held-out block has fitted neighbours.
//
// The statistic is the same on the residual and on every surrogate: the share of the residual's
// sum of squares that least squares on the candidate's design removes. An effect's design is its
// correction at the fit and its Jacobian there (the directions it can move in); a formula's is the
// catalogue, of which the same number of terms is chosen greedily on each surrogate as on the
// residual (the search's selection is part of the null; the formula's per-channel levels are taken
// first, as the search takes them). The surrogates are of the residual itself: under the null it is
// the noise. Surrogates of what a candidate leaves were tried and are too lenient: a gain and
// offset that follow a random walk take its slowest modes, and what they leave is a faster noise
// (a brown noise's offsets were claimed at p = 0.005; of the residual, p > 0.01). Several candidates
// are tested at once, Bonferroni over the family, so the chance that such noise gives any claim is
// at most the level.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Dense>

namespace gc {

/// `count` surrogates of `residual` (rows in time order, one column per moment channel): each
/// channel's periodogram kept, the same random phase added to both channels at each frequency (their
/// cross-spectrum kept), and each channel's mean drawn from its power at the lowest frequencies
/// rather than kept: a level is what a slow noise wanders to as much as a calibration offset.
std::vector<Eigen::MatrixX2d> phase_randomised_surrogates(const Eigen::MatrixX2d& residual, int count,
                                                          std::uint64_t seed);

/// A candidate's design on the rows: columns stacked as the residual is (rows k for M_sy', n + k for
/// M_sz'). `choose` 0: every column; k > 0: the k columns forward selection takes (orthogonal
/// matching pursuit on normalised columns), on the residual and on each surrogate alike.
struct SurrogateDesign {
  Eigen::MatrixXd columns;  ///< 2n x p [N·m per unit of each column's coefficient]
  int choose = 0;
  /// Columns always in the fit, the choice made on what they leave (2n x q; may be empty): a
  /// formula's per-channel levels, as the formula search takes intercepts before any term.
  Eigen::MatrixXd forced;
};

/// Share of the stacked `residual`'s sum of squares that least squares on `design` removes, in [0, 1].
double explained_share(const SurrogateDesign& design, const Eigen::MatrixX2d& residual);

/// Per design, the p-value that noise with the residual's spectrum is explained as well, times the
/// number of designs (Bonferroni over the family): (1 + surrogates
/// explained at least as well) / (1 + surrogates drawn). Enough surrogates are drawn for a p-value
/// of half `level`, fewer once the p-value is sure to be above it (Besag and Clifford, 1991).
std::vector<double> surrogate_p_values(const Eigen::MatrixX2d& residual, const std::vector<SurrogateDesign>& designs,
                                       double level, std::uint64_t seed);

}  // namespace gc
