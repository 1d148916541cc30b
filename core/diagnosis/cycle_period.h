// The period of a slow cycle in the residual over time: a bridge zero that swings with the test
// cell's temperature control (air or oil cycling about its set point) is a sine in time that no
// polynomial in t follows for long. A periodogram with a quadratic trend (the drift the t and t^2
// terms take) and the inputs as nuisance picks the period whose sine and cosine explain most of
// both channels; the
// discrepancy stage then offers time_cycle terms of that period (core/effects/expression_terms.h)
// and its cross-validation and drift rule decide whether they stay. A period at which an input
// (torque, misalignment, speed, temperature) swings is not offered: a residual on that rhythm is
// the input's effect, and the catalogue's terms of the input say so in physics.
#pragma once

#include <optional>
#include <span>

#include <Eigen/Dense>

#include "core/recorded_sample.h"

namespace gc {

/// Periods scanned: from a twentieth of the recording's span (and 2 s) to two thirds of it, so that
/// a found cycle repeats at least one and a half times.
inline constexpr double kCyclesInSpanMost = 20.0, kCyclesInSpanLeast = 1.5;

/// The period [s, whole seconds] that best explains `residual` (rows k of observations[rows[k]]), or
/// nullopt when the span holds no such period.
std::optional<double> dominant_cycle_period(std::span<const RecordedSample> observations,
                                            std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual);

}  // namespace gc
