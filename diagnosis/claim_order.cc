#include "diagnosis/claim_order.h"

#include <algorithm>

#include "diagnosis/alike_candidates.h"
#include "diagnosis/claim_rule.h"
#include "diagnosis/paired_block_test.h"

namespace gc {

void put_claim_first(std::vector<CandidateScore>& ranking, double base_ms, double noise_ms, const Folds& folds,
                     const DiagnosisSettings& settings) {
  if (ranking.empty() || plausible(ranking.front())) return;
  for (std::size_t k = 1; k < ranking.size(); ++k) {
    if (!claimable(ranking[k], base_ms, noise_ms, settings) || !plausible(ranking[k])) continue;
    const PairedBlockTest t = paired_block_test(ranking[k].held_out_residual, ranking.front().held_out_residual,
                                                folds.block_of, folds.blocks);
    if (t.t < settings.alike_t) std::rotate(ranking.begin(), ranking.begin() + static_cast<std::ptrdiff_t>(k),
                                             ranking.begin() + static_cast<std::ptrdiff_t>(k) + 1);
    return;
  }
}

void put_simpler_swap_first(std::vector<CandidateScore>& ranking, const Folds& folds, const DiagnosisSettings& settings) {
  if (ranking.empty() || !ranking.front().replaces.empty() || !ranking.front().info) return;
  const CandidateScore& first = ranking.front();
  for (std::size_t k = 1; k < ranking.size(); ++k) {
    const CandidateScore& swap = ranking[k];
    if (swap.replaces.empty() || !swap.failure.empty() || !swap.info ||
        swap.info->parameters.size() >= first.info->parameters.size()) {
      continue;
    }
    const PairedBlockTest t = paired_block_test(swap.held_out_residual, first.held_out_residual, folds.block_of, folds.blocks);
    const bool close = swap.held_out_rmse_nm <= (1.0 + settings.alike_rmse_share) * first.held_out_rmse_nm;
    if (close || t.t < settings.alike_t) {
      std::rotate(ranking.begin(), ranking.begin() + static_cast<std::ptrdiff_t>(k),
                  ranking.begin() + static_cast<std::ptrdiff_t>(k) + 1);
    }
    return;
  }
}

void put_simplest_alike_first(std::vector<CandidateScore>& ranking, const Eigen::MatrixX2d& base, const Folds& folds,
                              double base_ms, double noise_ms, const DiagnosisSettings& settings) {
  if (ranking.empty() || !ranking.front().info || !claimable(ranking.front(), base_ms, noise_ms, settings)) return;
  std::size_t simplest = 0;
  for (std::size_t k = 1; k < ranking.size(); ++k) {
    const CandidateScore& c = ranking[k];
    // Plausible or not: a range is advice, and a simpler effect a little past its range names what
    // the data shows as well as one with more parameters that stays within theirs. One held on a
    // physical bound cannot say how far beyond it the truth lies, and does not take the place.
    if (!c.info || !c.replaces.empty() || !claimable(c, base_ms, noise_ms, settings) || at_bound(c)) continue;
    if (fitted_parameter_count(c) >= fitted_parameter_count(ranking[simplest])) continue;
    double similarity = 0.0;
    PairedBlockTest t;
    if (alike(ranking.front(), c, base, folds, settings, similarity, t)) simplest = k;
  }
  if (simplest > 0) {
    std::rotate(ranking.begin(), ranking.begin() + static_cast<std::ptrdiff_t>(simplest),
                ranking.begin() + static_cast<std::ptrdiff_t>(simplest) + 1);
  }
}

}  // namespace gc
