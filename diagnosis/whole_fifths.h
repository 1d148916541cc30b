// The claim's second held-out test: whole fifths of the recording. The cross-validation deals short
// blocks to the folds so that every fold sees the whole load sequence; but then every held-out
// block has fitted neighbours, and a candidate that follows a slow wander of the noise (a random
// walk, an AR(1) of phi 0.994, a zero that drifts) through an input that moves slowly with time
// predicts them: a thermal misalignment took 9.7 % of a random walk's error at t = 3.8 that way.
// Fitted on four contiguous fifths and judged on the fifth it never came near, a physical effect
// still predicts (it is physics: it extrapolates), and a wander does not.
#pragma once

#include <cstddef>

#include <Eigen/Dense>

#include "diagnosis/cross_validation_folds.h"

namespace gc {

/// Five folds, each a contiguous fifth of `count` positions, the paired tests' blocks
/// `rows_per_block` positions each.
Folds whole_fifths(std::size_t count, std::size_t rows_per_block);

/// The paired t a claim must reach on whole fifths: one-sided p about 0.03 with the noise's
/// long-run inflation (paired_block_test.h). A second test, not the first again: it only has to
/// show that the gain carries across the recording.
constexpr double kWholeFifthsT = 2.0;

/// Whether `held_out` (a candidate's residual on whole_fifths' held-out folds) beats `base` there:
/// a positive mean gain with a paired t of at least kWholeFifthsT.
bool carries_to_whole_fifths(const Eigen::MatrixX2d& base, const Eigen::MatrixX2d& held_out, const Folds& fifths);

}  // namespace gc
