// The signature of a residual: against which recorded input it is systematic, and how. The
// residual is binned by each input (torque, misalignment amplitude and direction, loading
// direction, time, and speed and temperature where every row has them); an input is systematic
// when its bin means scatter more than the noise allows.
#pragma once

#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/recorded_sample.h"

namespace gc {

struct SignatureBin {
  double lower = 0.0, upper = 0.0;  ///< input range of the bin [input unit]
  std::size_t count = 0;
  double mean_y_nm = 0.0, mean_z_nm = 0.0;  ///< mean residual of M_sy', M_sz' [N·m]
};

struct InputSignature {
  std::string input;  ///< "torque", "misalignment", "direction", "loading_direction", "time", ...
  std::string unit;   ///< SI unit of the bin bounds and slope
  std::vector<SignatureBin> bins;
  /// Share of the residual's sum of squares that the bin means carry (0..1).
  double explained_share = 0.0;
  /// The analysis-of-variance F: between-bin over within-bin mean square, for the worse channel;
  /// about 1 when the residual does not depend on this input.
  double dispersion = 0.0;
  bool systematic = false;      ///< F beyond the 1e-4 quantile (chi-square approximation)
  double slope_y = 0.0, slope_z = 0.0;  ///< least-squares trend [N·m per input unit]
};

struct ResidualSignature {
  std::vector<InputSignature> inputs;  ///< most explaining first
  bool systematic() const;
};

/// `residual` row k belongs to observations[rows[k]]. Bins: 8 of equal count (continuous inputs), 8 of 45 deg
/// (direction and rotation phase), one per loading direction. `variance_inflation`: the noise's
/// (NoiseEstimate::variance_inflation): the samples of a bin are mostly neighbours in time, so a
/// correlated noise scatters the bin means that much more than a white one, and F is judged against it.
ResidualSignature residual_signature(std::span<const RecordedSample> observations,
                                     std::span<const std::size_t> rows,
                                     const Eigen::MatrixX2d& residual, double variance_inflation = 1.0);

}  // namespace gc
