// Whether one model predicts held-out data better than another: a paired t statistic on the
// per-block mean difference of squared errors. Blocks (contiguous in time) rather than single
// samples, because neighbouring errors are correlated and a per-sample test would overstate
// the evidence. The block means are winsorized at 1 % either end (a transient of one block must not
// carry the variance of the whole test), and the blocks are cut as long as the noise's correlation
// needs (cross_validation_folds.h, with_test_blocks).
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace gc {

struct PairedBlockTest {
  double mean_difference = 0.0;  ///< mean over blocks of (|a|^2 - |b|^2) / 2 [N²·m²]
  double t = 0.0;                ///< mean / (sd / sqrt(blocks)); 0 when undefined
  int blocks = 0;
};

/// Positive t: `b` has the smaller errors. `block_of[i]` is row i's block in [0, blocks).
PairedBlockTest paired_block_test(const Eigen::MatrixX2d& a, const Eigen::MatrixX2d& b,
                                  const std::vector<int>& block_of, int blocks);

}  // namespace gc
