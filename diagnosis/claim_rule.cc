#include "diagnosis/claim_rule.h"

#include <algorithm>

namespace gc {

bool claimable(const CandidateScore& c, double base_ms, double noise_ms, const DiagnosisSettings& settings) {
  if (!c.failure.empty() || c.against_base.t < settings.claim_t) return false;
  const double effect_ms = c.held_out_rmse_nm * c.held_out_rmse_nm;
  const double excess = std::max(base_ms - noise_ms, 0.0);
  const double fall = base_ms - effect_ms;
  return fall >= settings.claim_excess_share * excess && fall >= settings.claim_least_fall * base_ms && fall > 0.0;
}

bool plausible(const CandidateScore& c) { return c.fit && c.fit->plausible(); }

bool at_bound(const CandidateScore& c) { return !c.fit || c.fit->at_bound(); }

}  // namespace gc
