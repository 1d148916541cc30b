// The period of a cycle in the residual over time that no input explains: a bridge zero that swings
// with the test cell's temperature control (tens of seconds to hours), or an interference at a fixed
// frequency (pickup from a pump or a converter, a rig resonance: tenths of a second to seconds).
// A polynomial in t follows neither for long. The residual, less a quadratic trend (the drift the
// t and t^2 terms take) and the inputs (nuisance), is binned onto a uniform grid in time and its
// periodogram taken by FFT (zero-padded twice) from a period of two thirds of the span down to the
// Nyquist period of the rows; the strongest peaks are then scored exactly by least squares (the
// sine and cosine of the period beside the nuisance, on both channels) and the best refined by a
// golden-section search within one bin. The discrepancy stage offers time_cycle terms of that
// period (core/effects/expression_terms.h), and its cross-validation and drift rule decide whether
// they stay. A period at which an input (torque, misalignment, speed, temperature) swings is not
// offered: a residual on that rhythm is the input's effect, and the catalogue's terms of the input
// say so in physics.
//
// On a long recording the rows given should be dense (the diagnosis passes its refit rows, at most
// 20,000): the search rows of a 100,000-row recording are 67 samples apart, and an interference at
// 0.4 Hz aliases on them.
#pragma once

#include <optional>
#include <span>

#include <Eigen/Dense>

#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// The longest period scanned is the span over this, so that a found cycle repeats 1.5 times.
inline constexpr double kCyclesInSpanLeast = 1.5;

/// The period [s] that best explains `residual` (rows k of observations[rows[k]], in time order);
/// nullopt when the span holds no such period. The periodogram's peaks are refined side by side
/// with `parallel`; the answer does not depend on it.
std::optional<double> dominant_cycle_period(std::span<const RecordedSample> observations,
                                            std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                            const ParallelFor& parallel = serial_for());

}  // namespace gc
