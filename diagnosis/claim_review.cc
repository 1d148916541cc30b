#include "diagnosis/claim_review.h"

#include "diagnosis/model_residuals.h"
#include "diagnosis/paired_block_test.h"

namespace gc {

std::vector<std::string> redundant_claims(const CouplingModel& model, const std::vector<std::string>& earlier,
                                          const Eigen::MatrixX2d& held_out,
                                          std::span<const RecordedSample> observations,
                                          std::span<const std::size_t> rows, const Folds& folds,
                                          const ParallelFor& parallel, double keep_t) {
  std::vector<std::string> drop;
  for (const std::string& name : earlier) {
    const ModelResiduals without = model_residuals(model.without_effect(name), observations, rows, parallel);
    if (!without.failed_rows.empty()) continue;
    if (paired_block_test(without.residual, held_out, folds.block_of, folds.blocks).t < keep_t) drop.push_back(name);
  }
  return drop;
}

}  // namespace gc
