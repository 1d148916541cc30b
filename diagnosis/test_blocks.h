// The blocks of the paired tests (paired_block_test.h): how many rows a block holds, so that block
// means of correlated noise are nearly independent.
#pragma once

#include <cstddef>

#include "diagnosis/cross_validation_folds.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/noise_estimate.h"

namespace gc {

/// Search rows per block of the paired tests: three times the variance inflation of the noise's
/// correlation between neighbouring search rows (lag-1 correlation phi^stride for search rows
/// `stride` samples apart), so that block means are nearly independent; at most the rows of the
/// cross-validation's blocks, the most a test needs.
std::size_t test_block_rows(const NoiseEstimate& noise, std::size_t rows, std::size_t search,
                            const DiagnosisSettings& settings);

/// The paired tests' block length of `folds` [rows].
std::size_t test_rows_per_block(const Folds& folds);

}  // namespace gc
