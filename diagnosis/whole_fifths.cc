#include "diagnosis/whole_fifths.h"

#include "diagnosis/paired_block_test.h"

namespace gc {

Folds whole_fifths(std::size_t count, std::size_t rows_per_block) {
  return with_test_blocks(blocked_folds(count, 5, 1), rows_per_block);
}

bool carries_to_whole_fifths(const Eigen::MatrixX2d& base, const Eigen::MatrixX2d& held_out, const Folds& fifths) {
  const PairedBlockTest t = paired_block_test(base, held_out, fifths.block_of, fifths.blocks, true);
  return t.mean_difference > 0.0 && t.t >= kWholeFifthsT;
}

}  // namespace gc
