// A cycle at the mains frequency is the instrument's, not the coupling's: the bridges and their
// cables pick up 50 or 60 Hz (and its harmonics) from the test cell's drives, and a DAQ that samples
// slower than that sees it aliased to a lower frequency. Reported as a data-quality finding, never
// offered to the physics: a noise zoo's mains pickup with a wandering frequency was claimed as a
// "time cycle of 0.0200218 s" with two shaft-order terms beside it.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/recorded_sample.h"

namespace gc {

/// The mains frequency (50 or 60 Hz, or its 2nd or 3rd harmonic) that a cycle of `frequency_hz`
/// seen at `sample_rate_hz` is, directly or aliased, within `resolution_hz` (about 1 / the
/// recording's duration) plus 0.5 % of that mains frequency (the grid's deviation, which aliasing
/// keeps in hertz) [Hz]; nullopt when none.
std::optional<double> mains_frequency(double frequency_hz, double sample_rate_hz, double resolution_hz);

/// "a cycle at 50.0 Hz (mains pickup ...)" for the verdict.
std::string mains_pickup_text(double cycle_hz, double mains_hz);

/// Removes from `time_terms` a cycle at the mains frequency (mains_frequency), or a ringing mode
/// damped under 0.05 whose natural frequency is there (a narrow line as well), direct or aliased by
/// the rows' sample rate, and returns what the verdict says of it ("" when none). An aliased one is
/// kept where a shaft or tooth-mesh order of a coupling of `teeth` (0: unknown) at a speed the
/// rows recorded lies as near, unless `residual` (one row per `rows`) shows the line as well on
/// the rows at speeds where no order is near: only there can the data tell the two apart.
std::string take_out_mains_cycles(std::vector<std::string>& time_terms, std::span<const RecordedSample> observations,
                                  const std::vector<std::size_t>& rows, const Eigen::MatrixX2d& residual, int teeth);

}  // namespace gc
