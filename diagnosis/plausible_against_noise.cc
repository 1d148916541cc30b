#include "diagnosis/plausible_against_noise.h"

#include <algorithm>

#include "diagnosis/claim_rule.h"
#include "diagnosis/stacked_channels.h"
#include "diagnosis/surrogate_test.h"

namespace gc {
namespace {

/// A candidate that adds one effect of the library (not a refit of earlier claims or a swap).
bool single_effect(const CandidateScore& c) {
  return c.fit && c.fit->effect && c.replaces.empty() && c.fit->effect->members().empty();
}

}  // namespace

void put_plausible_first_unless_beyond_noise(
    std::vector<CandidateScore>& ranking, const CouplingModel& model, std::span<const RecordedSample> observations,
    std::span<const std::size_t> rows, const Eigen::MatrixX2d& base, const ParallelFor& parallel,
    const std::function<bool(const CandidateScore&)>& claimable,
    const std::function<std::optional<EffectRegistration>(const Effect&)>& registration_for,
    const SurrogateClaimSettings& settings) {
  if (ranking.empty() || !(settings.level > 0.0)) return;
  CandidateScore& first = ranking.front();
  if (!first.failure.empty() || !claimable(first) || plausible(first) || !single_effect(first)) return;
  const auto other = std::find_if(ranking.begin() + 1, ranking.end(), [&](const CandidateScore& c) {
    return c.failure.empty() && claimable(c) && plausible(c) && single_effect(c);
  });
  if (other == ranking.end()) return;
  const std::optional<EffectRegistration> first_registration = registration_for(*first.fit->effect);
  const std::optional<EffectRegistration> other_registration = registration_for(*other->fit->effect);
  if (!first_registration || !other_registration) return;
  const std::optional<SurrogateDesign> first_design =
      effect_design(first, *first_registration, model, observations, rows, base, parallel);
  const std::optional<SurrogateDesign> other_design =
      effect_design(*other, *other_registration, model, observations, rows, base, parallel);
  if (!first_design || !other_design || other_design->columns.cols() == 0) return;
  // What the plausible candidate leaves: the residual less its correction at the fit.
  const Eigen::MatrixX2d left = base - unstacked(other_design->columns.col(0));
  const double p = surrogate_p_values(left, {*first_design}, settings.level, settings.seed ^ 0x9a55'1b1e)[0];
  if (p <= settings.level) return;
  std::rotate(ranking.begin(), other, other + 1);
}

}  // namespace gc
