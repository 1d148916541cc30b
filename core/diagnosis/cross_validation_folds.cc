#include "core/diagnosis/cross_validation_folds.h"

#include <algorithm>

namespace gc {

Folds blocked_folds(std::size_t count, int folds, int blocks_per_fold) {
  Folds out;
  out.training.resize(static_cast<std::size_t>(folds));
  out.held_out.resize(static_cast<std::size_t>(folds));
  out.blocks = static_cast<int>(std::min<std::size_t>(count, static_cast<std::size_t>(folds * blocks_per_fold)));
  out.block_of.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const int block = static_cast<int>(i * static_cast<std::size_t>(out.blocks) / count);
    out.block_of[i] = block;
    const int fold = block % folds;
    for (int f = 0; f < folds; ++f) (f == fold ? out.held_out : out.training)[static_cast<std::size_t>(f)].push_back(i);
  }
  return out;
}

}  // namespace gc
