// Building blocks of the noise families: unit processes and filters over one channel's samples.
// Every function is dimensionless unless stated; scale_to gives a series its level in N·m.
#pragma once

#include <cstddef>
#include <vector>

#include "tests/diagnosis/zoo/rng.h"

namespace gc::zoo {

using Series = std::vector<double>;

/// Subtracts the mean (a constant offset is a calibration, not noise) and scales the RMS to `rms`.
/// A series with no spread is left at zero.
void scale_to(Series& x, double rms);
double rms_about_mean(const Series& x);
double mean(const Series& x);

Series white(std::size_t n, Rng& rng);
/// x_i = phi x_(i-1) + sqrt(1 - phi^2) e_i, stationary from the first sample, unit variance.
Series ar1(std::size_t n, double phi, Rng& rng);
/// AR(2) with poles r exp(+-i 2 pi f), f in cycles per sample: a noise peak of relative width
/// about (1 - r) / pi cycles per sample at f.
Series ar2_resonant(std::size_t n, double f_cycles_per_sample, double r, Rng& rng);
/// 1/f noise: the sum of OU processes with time constants an octave apart from 1 sample to the
/// whole record, each of equal variance (Voss/McCartney's idea with exponential memories).
Series pink(std::size_t n, Rng& rng);
/// A random walk (1/f^2): the running sum of white noise.
Series brown(std::size_t n, Rng& rng);
/// Direct-form biquad (RBJ cookbook) run on x: low-pass or band-pass at f (cycles per sample, < 0.5).
Series lowpass2(const Series& x, double f_cycles_per_sample, double q);
Series bandpass2(const Series& x, double f_cycles_per_sample, double q);
/// Trailing moving average over m samples (m >= 1).
Series moving_average(const Series& x, std::size_t m);
/// Trailing average over a window of varying length window[i] samples (>= 1), by prefix sums.
Series varying_average(const Series& x, const std::vector<double>& window);

}  // namespace gc::zoo
