// Whether one model predicts held-out data better than another: a paired t statistic on the
// per-block mean difference of squared errors. Blocks (contiguous in time) rather than single
// samples, because neighbouring errors are correlated and a per-sample test would overstate
// the evidence. The block means are winsorized at 1 % either end (a transient of one block must not
// carry the variance of the whole test), and the blocks are cut as long as the noise's correlation
// needs (cross_validation_folds.h, with_test_blocks).
//
// The block means are not taken for independent: the t's variance is inflated by the **long-run
// inflation of the noise** at the scale of the blocks, measured on the better model's held-out
// residual (what is left is the noise): its block means batched over 1, 2, 4, ... consecutive
// blocks (at least 10 batches), the largest ratio of the batch means' variance to what independent
// blocks would give. A correlation longer than a block (a correlated part hidden under white noise,
// a 1/f or wandering noise) makes neighbouring block means alike, and a test that counted them as
// independent trusted a count of rows the recording does not have. The noise's, not the
// difference's: an effect strong in one part of a sweep and weak in another makes the difference
// vary slowly by itself, and its own batch means took a 30-fold effect for noise.
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace gc {

struct PairedBlockTest {
  double mean_difference = 0.0;  ///< mean over blocks of (|a|^2 - |b|^2) / 2 [N²·m²]
  double t = 0.0;                ///< mean / its long-run standard error; 0 when undefined
  int blocks = 0;
  double inflation = 1.0;        ///< the noise's long-run inflation of the block means' variance (>= 1)
};

/// Positive t: `b` has the smaller errors. `block_of[i]` is row i's block in [0, blocks), blocks
/// numbered in time order. `long_run`: the block means' variance inflated by the noise's long-run
/// correlation (above): the test of a claim against the model, which decides whether anything is
/// claimed at all. Without it the blocks count as independent: the comparisons between candidates
/// that are each claimable already (which goes first, whether one is idle beside another), where the
/// noise they share cancels in the difference.
PairedBlockTest paired_block_test(const Eigen::MatrixX2d& a, const Eigen::MatrixX2d& b,
                                  const std::vector<int>& block_of, int blocks, bool long_run = false);

/// How much the correlation of `series` (in time order) inflates the variance of its mean over what
/// independent values would give: for batches of 1, 2, 4, ... consecutive values that leave at least
/// `least_batches` batches, the batch means' variance times the batch length over the values'
/// variance; the largest, at least 1 (about 1 for an independent series).
double long_run_ratio(const Eigen::VectorXd& series, int least_batches = 10);

}  // namespace gc
