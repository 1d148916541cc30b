// The signature of a residual: against which recorded input it is systematic, and how. The
// residual is binned by each input (torque, misalignment amplitude and direction, loading
// direction, time, and speed, temperature and rotation phase where every row has them) and
// attributed to all inputs at once: an additive model r = mu + sum_j f_j(bin of input j), fitted by
// backfitting, so that f_j is the residual's dependence on input j *given the others* (partial
// dependence) and an input that merely correlates with the cause (temperature rising with time)
// does not take the cause's share. An input is systematic when its f_j scatters more than the
// noise allows. Inputs that move together so closely that this recording cannot separate them are
// named as such.
#pragma once

#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"

namespace gc {

struct SignatureBin {
  double lower = 0.0, upper = 0.0;  ///< input range of the bin [input unit]
  std::size_t count = 0;
  /// Partial dependence: the additive model's term for this bin, M_sy', M_sz' [N·m] (the mean of
  /// the residual in the bin once the other inputs' terms are taken off, centred).
  double mean_y_nm = 0.0, mean_z_nm = 0.0;
};

struct InputSignature {
  std::string input;  ///< "torque", "misalignment", "direction", "loading_direction", "time", ...
  std::string unit;   ///< SI unit of the bin bounds and slope
  std::vector<SignatureBin> bins;
  /// Share of the residual's sum of squares that the partial bin means carry (0..1).
  double explained_share = 0.0;
  /// The same for the plain (marginal) bin means, one input at a time (0..1).
  double marginal_share = 0.0;
  /// F: the partial bin means' mean square over the additive model's residual mean square, for the
  /// worse channel, divided by the noise's variance inflation; about 1 when the residual does not
  /// depend on this input.
  double dispersion = 0.0;
  bool systematic = false;      ///< F beyond the 1e-4 quantile (chi-square approximation)
  double slope_y = 0.0, slope_z = 0.0;  ///< least-squares trend [N·m per input unit]
  /// Continuous inputs whose values correlate with this one at |r| >= 0.9 on this recording: the
  /// split of the residual between them is not to be trusted.
  std::vector<std::string> confounded_with;
};

struct ResidualSignature {
  std::vector<InputSignature> inputs;  ///< most explaining first
  /// The variance inflation the F tests were judged against: the caller's, or the long-run
  /// inflation of what the inputs leave (block means), when larger.
  double variance_inflation = 1.0;
  const InputSignature* find(const std::string& input) const;
  bool systematic() const;
};

/// `residual` row k belongs to observations[rows[k]]. Bins: 8 of equal count (continuous inputs), 8 of 45 deg
/// (direction and rotation phase), one per loading direction. `variance_inflation`: the noise's
/// (NoiseEstimate::variance_inflation): the samples of a bin are mostly neighbours in time, so a
/// correlated noise scatters the bin means that much more than a white one, and F is judged against it.
/// The inputs' leave-one-out fits run side by side with `parallel`.
ResidualSignature residual_signature(std::span<const RecordedSample> observations,
                                     std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                     const ParallelFor& parallel, double variance_inflation = 1.0);

/// The bin of every row of `rows` for `input` (an InputSignature::input name), cut as the signature
/// cuts it; empty when the input is unknown or a row lacks it.
std::vector<int> signature_bins(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                const std::string& input);

}  // namespace gc
