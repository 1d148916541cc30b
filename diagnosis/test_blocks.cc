#include "diagnosis/test_blocks.h"

#include <algorithm>
#include <cmath>

namespace gc {

std::size_t test_block_rows(const NoiseEstimate& noise, std::size_t rows, std::size_t search,
                            const DiagnosisSettings& settings) {
  const double stride = static_cast<double>(rows) / static_cast<double>(std::max<std::size_t>(1, search));
  const double phi = std::pow(std::clamp(noise.phi.maxCoeff(), 0.0, 0.99), stride);
  const auto wanted = static_cast<std::size_t>(std::ceil(3.0 * (1.0 + phi) / (1.0 - phi)));
  const std::size_t coarsest = search / static_cast<std::size_t>(settings.cross_validation.folds *
                                                                  settings.cross_validation.blocks_per_fold);
  return std::clamp<std::size_t>(wanted, 2, std::max<std::size_t>(2, coarsest));
}

std::size_t test_rows_per_block(const Folds& folds) {
  return folds.blocks > 0 ? (folds.block_of.size() + static_cast<std::size_t>(folds.blocks) - 1) /
                                static_cast<std::size_t>(folds.blocks)
                          : 2;
}

}  // namespace gc
