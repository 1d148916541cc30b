#include "diagnosis/partly_claims.h"

#include <algorithm>

#include "core/effects/expression.h"
#include "diagnosis/claimed_effects.h"

namespace gc {

std::optional<JointEffect> partly_claims_together(const CouplingModel& model, const CouplingModel& given,
                                                  const std::set<std::string>& partly, const DiagnosisSettings& settings) {
  constexpr std::size_t kMostMembers = 3;
  std::vector<std::shared_ptr<const Effect>> added;
  for (const auto& effect : model.effects()) {
    if (given.has_effect(effect->name()) || effect->name() == kExpressionEffect) continue;
    const std::optional<EffectRegistration> registration = registration_for(*effect, settings);
    if (!registration || registration->info->parameters.empty()) continue;
    added.push_back(effect);
  }
  if (added.size() > kMostMembers) added.erase(added.begin(), added.end() - kMostMembers);
  const bool any_partly = std::any_of(added.begin(), added.end(), [&](const auto& e) { return partly.count(e->name()) > 0; });
  if (added.size() < 2 || !any_partly) return std::nullopt;
  return joint_of(added, settings);
}

CrossValidationSettings joint_refit_settings(CrossValidationSettings settings) {
  settings.fit.probe_points = std::max(settings.fit.probe_points, 64);
  settings.fit.starts = std::max(settings.fit.starts, 6);
  settings.fit.least_squares.max_iterations = std::max(settings.fit.least_squares.max_iterations, 20);
  return settings;
}

std::optional<std::string> rival_of_claim(const DiagnosisRound& round, const CouplingModel& given) {
  if (round.outcome != RoundOutcome::partly_explained || round.formula_chosen || round.ranking.empty()) return std::nullopt;
  const CandidateScore& best = round.ranking.front();
  if (best.kind != CandidateKind::addition || !best.info) return std::nullopt;
  for (std::size_t k = 1; k < round.ranking.size(); ++k) {
    const CandidateScore& c = round.ranking[k];
    if (c.held_out_rmse_nm > (1.0 + kRivalShare) * best.held_out_rmse_nm) break;
    if (c.kind == CandidateKind::refinement && c.failure.empty() && c.info && given.has_effect(c.info->name) &&
        c.info->parameters.size() < best.info->parameters.size()) {
      return c.info->name;
    }
  }
  return std::nullopt;
}

}  // namespace gc
