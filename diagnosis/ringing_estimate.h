// The rig's own dynamics in the residual: a lightly damped mode of the rig (its structure, a stiff
// shaft, the dynamometer's torsional mode) that a change of the load sets ringing, which the
// model's static moments cannot follow. Its term is the torque passed through a second-order
// system less the torque itself, h * T - T (core/effects/ringing_response.h), on each channel; its
// natural frequency f_n and damping ratio zeta are found here, on the dense rows, by a search over
// a grid (f_n log-spaced by 5 % from 0.2 Hz to 0.9 of the rows' Nyquist frequency, zeta from 0.01
// to 0.2: a mode damped more barely rings) of what the pair of columns explains beside a nuisance
// (a constant, t, T and zeta: the level and the static part of a mis-modelled moment, which a
// step's ringing column shares, since its integral is -2 zeta / w_n per unit step), refined by
// golden sections in f_n and zeta. The mode is offered only when it stands out of the noise: what
// it explains, over the noise variance the rest leaves times the noise's variance inflation
// (1 + phi) / (1 - phi), exceeds what the largest of the grid's chi-square(2) statistics reaches
// once in a thousand in pure noise (the cycle period's rule, cycle_period.h), and when the grid finds
// more in the residual than in each of 19 copies of it turned round in time against the load (a
// ringing is locked to the load's changes; narrowband noise is not, and its spectral peak hides from
// a lag-1 inflation).
#pragma once

#include <optional>
#include <span>

#include <Eigen/Dense>

#include "core/effects/ringing_response.h"
#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// The mode whose torque ringing best explains `residual` (rows k of observations[rows[k]], in time
/// order; the ringing itself from every observation, in the recording's order); nullopt when the
/// torque does not change or no mode stands out of the noise. The grid's frequencies are shared
/// over `parallel`; the result does not depend on how.
std::optional<RingingMode> dominant_ringing(std::span<const RecordedSample> observations,
                                            std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                            const ParallelFor& parallel = serial_for());

}  // namespace gc
