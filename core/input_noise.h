// The white noise on a recorded input (misalignment, torque), estimated from the series itself,
// so that thresholds on that input can follow the recording rather than a fixed guess (issue 8).
#pragma once

#include <span>

namespace gc {

/// Standard deviation [unit of the series] of white noise on `series`, samples in time order:
/// 1.4826 * MAD(d) / sqrt(6), d_i = x_{i-1} - 2 x_i + x_{i+1}. A second difference removes a
/// constant and a ramp exactly, so holds and steady ramps add nothing; white noise of sigma
/// gives var(d) = (1 + 4 + 1) sigma^2; the median absolute deviation (1.4826 MAD = sigma for
/// normal d) ignores the few d at the corners between holds and ramps. Zero for fewer than three
/// samples. Sample spacing does not enter: the noise is per sample.
double input_noise_sigma(std::span<const double> series);

}  // namespace gc
