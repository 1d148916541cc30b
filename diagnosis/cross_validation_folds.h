// The folds of the cross-validation. Rows are cut into short contiguous blocks in time and the
// blocks dealt to the folds in turn (block b to fold b mod k). Contiguous blocks keep
// neighbouring samples, whose noise and sawtooth are correlated, on the same side of the split,
// so the held-out error is not flattered by leakage; dealing many blocks round-robin gives every
// fold rows from the whole load sequence, so no fold has to extrapolate to a torque or
// misalignment range it never saw (which whole-fold time blocks would demand of a single sweep).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gc {

struct Folds {
  std::vector<std::vector<std::size_t>> training;  ///< per fold, positions into the row list
  std::vector<std::vector<std::size_t>> held_out;  ///< per fold
  std::vector<int> block_of;                       ///< per position, its block (for paired tests)
  int blocks = 0;
};

/// `rows` positions 0..count-1 in time order; `folds` >= 2, `blocks_per_fold` >= 1; fewer blocks
/// when there are fewer rows than blocks. Seed 0 deals blocks round-robin; another seed deals each
/// run of `folds` consecutive blocks to the folds in a shuffled order (still every fold once per run,
/// so every fold still sees the whole load sequence), to show a verdict does not hang on the cut.
Folds blocked_folds(std::size_t count, int folds, int blocks_per_fold, std::uint64_t seed = 0);

/// The blocks of the paired tests cut again, `rows_per_block` contiguous positions each (at least
/// 2), the folds unchanged. A block must outlast the noise's correlation, no more: an effect that
/// lives in transients (a skew shows only while the inputs move) carries its gain in few rows,
/// and a test over 100 blocks cannot find it significant however large it is, for its gain falls
/// in a tenth of them (t at most sqrt(100 x 0.1 / 0.9) = 3.3).
Folds with_test_blocks(Folds folds, std::size_t rows_per_block);

}  // namespace gc
