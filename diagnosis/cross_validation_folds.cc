#include "diagnosis/cross_validation_folds.h"

#include <algorithm>
#include <numeric>
#include <random>

namespace gc {

namespace {

/// Fold of each block: run r of `folds` blocks gets a permutation of 0..folds-1 drawn from the seed.
std::vector<int> fold_of_blocks(int blocks, int folds, std::uint64_t seed) {
  std::vector<int> fold(static_cast<std::size_t>(blocks));
  std::mt19937_64 random(seed);
  std::vector<int> order(static_cast<std::size_t>(folds));
  for (int start = 0; start < blocks; start += folds) {
    std::iota(order.begin(), order.end(), 0);
    if (seed != 0) std::shuffle(order.begin(), order.end(), random);
    for (int k = 0; k < folds && start + k < blocks; ++k) fold[static_cast<std::size_t>(start + k)] = order[static_cast<std::size_t>(k)];
  }
  return fold;
}

}  // namespace

Folds blocked_folds(std::size_t count, int folds, int blocks_per_fold, std::uint64_t seed) {
  Folds out;
  out.training.resize(static_cast<std::size_t>(folds));
  out.held_out.resize(static_cast<std::size_t>(folds));
  out.blocks = static_cast<int>(std::min<std::size_t>(count, static_cast<std::size_t>(folds * blocks_per_fold)));
  out.block_of.resize(count);
  const std::vector<int> fold_of = fold_of_blocks(out.blocks, folds, seed);
  for (std::size_t i = 0; i < count; ++i) {
    const int block = static_cast<int>(i * static_cast<std::size_t>(out.blocks) / count);
    out.block_of[i] = block;
    const int fold = fold_of[static_cast<std::size_t>(block)];
    for (int f = 0; f < folds; ++f) (f == fold ? out.held_out : out.training)[static_cast<std::size_t>(f)].push_back(i);
  }
  return out;
}

Folds with_test_blocks(Folds folds, std::size_t rows_per_block) {
  const std::size_t per = std::max<std::size_t>(2, rows_per_block);
  for (std::size_t i = 0; i < folds.block_of.size(); ++i) folds.block_of[i] = static_cast<int>(i / per);
  folds.blocks = static_cast<int>((folds.block_of.size() + per - 1) / per);
  return folds;
}

}  // namespace gc
