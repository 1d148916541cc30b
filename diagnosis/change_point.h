// The time of a step in the residual: a bridge re-zeroed or re-balanced mid-test, a gauge or an
// amplifier replaced, a bolt that slipped. Each channel's residual, centred, is scanned by the
// CUSUM statistic of a single change in mean,
//   C(k) = |S_k - (k / n) S_n| / sqrt(k (n - k) / n),   S_k the sum of the first k values,
// the likelihood-ratio statistic for one change point under white noise (Page 1954; Hinkley 1970),
// over changes after the first twentieth of the rows and within the first 70 % (the forward test
// of a step needs rows after it), standardised by the scale
// and the long-run inflation (block means) of what the step leaves; offered when it exceeds 4. The
// larger over both channels gives the time (halfway between the two rows it separates). The discrepancy stage offers
// step terms at that time on each channel (core/effects/expression_terms.h); whether a step stays is
// for its held-out test and the drift rule (a step must predict whole fifths of the recording it
// was not fitted on), which judge it against the coloured noise that CUSUM alone would take for
// steps. The residual is only centred, not regressed on the inputs: a test programme changes its
// inputs by phases, and such a regression takes a step's share at a phase boundary near it.
#pragma once

#include <optional>
#include <span>

#include <Eigen/Dense>

#include "core/recorded_sample.h"

namespace gc {

/// The time [s] of the strongest single change in mean of `residual` (rows k of
/// observations[rows[k]], in time order); nullopt for fewer than 40 rows.
std::optional<double> dominant_step_time(std::span<const RecordedSample> observations,
                                         std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual);

}  // namespace gc
