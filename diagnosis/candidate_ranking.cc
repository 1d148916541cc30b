#include "diagnosis/candidate_ranking.h"

#include <algorithm>

#include "core/effects/expression.h"
#include "core/effects/joint_effect.h"
#include "diagnosis/candidates_side_by_side.h"
#include "diagnosis/claimed_effects.h"
#include "diagnosis/partly_claims.h"

namespace gc {
namespace {

bool has_held_shape(const EffectInfo& info) {
  return std::any_of(info.parameters.begin(), info.parameters.end(), [](const ParameterSpec& p) { return p.refine_only; });
}

}  // namespace

std::vector<CandidateScore> rank_candidates(const CouplingModel& model, std::span<const RecordedSample> observations,
                                            const std::vector<std::size_t>& search, const Eigen::MatrixX2d& base,
                                            const Folds& folds, const ParallelFor& parallel,
                                            const CouplingModel& given, const std::set<std::string>& partly,
                                            const std::map<std::string, std::string>& rivals,
                                            const DiagnosisSettings& given_settings,
                                            const std::vector<ParameterValues>& hints) {
  DiagnosisSettings settings = given_settings;
  for (const ParameterValues& hint : hints) settings.cross_validation.fit.hints.push_back(hint);
  std::vector<CandidateJob> jobs;  // scored side by side below (candidates_side_by_side.h)
  // An effect that needs an input no search row has changes nothing here (and costs a fit).
  const auto lacks_input = [&](const EffectInfo& info) {
    return std::any_of(info.requires_inputs.begin(), info.requires_inputs.end(), [&](OptionalInput input) {
      return std::none_of(search.begin(), search.end(), [&](std::size_t r) { return has_input(observations[r].input, input); });
    });
  };
  for (const EffectRegistration& registration : settings.library) {
    // The formula has its own stage; an effect the model has is a refinement below.
    if (registration.info->name == kExpressionEffect || model.has_effect(registration.info->name)) continue;
    if (lacks_input(*registration.info)) continue;
    jobs.push_back([&](const ParallelFor& rows) {
      return score_candidate(model, registration, observations, search, base, folds, rows, settings.cross_validation);
    });
  }
  if (settings.refinements) {
    for (const auto& effect : model.effects()) {
      // The given model's effects, those an earlier round added with a shape held
      // (ParameterSpec::refine_only), which only a refinement frees, and those an earlier round
      // said explain only partly: fitted beside what they did not explain, they took a share of it
      // (a thermal misalignment fitted beside an unexplained weight offset), and refitted once
      // that is explained they come right. Formulas added earlier are the formula stage's.
      if (!given.has_effect(effect->name()) && !has_held_shape(effect->info()) && !partly.count(effect->name())) continue;
      const std::optional<EffectRegistration> registration = registration_for(*effect, settings);
      if (!registration || registration->info->parameters.empty()) continue;
      jobs.push_back([&, registration = *registration, current = effect.get()](const ParallelFor& rows) {
        return score_candidate(model, registration, observations, search, base, folds, rows, settings.cross_validation,
                               current);
      });
    }
    if (const std::optional<JointEffect> joint = partly_claims_together(model, given, partly, settings)) {
      const CrossValidationSettings joint_cv = joint_refit_settings(settings.cross_validation);
      const std::optional<EffectRegistration> registration = registration_for(*joint, settings);
      if (registration) {
        jobs.push_back([&, registration = *registration, joint_cv, joint = *joint](const ParallelFor& rows) {
          return score_candidate(model, registration, observations, search, base, folds, rows, joint_cv, &joint);
        });
      }
      // The same refit with a member's rival in its place, on the model without that member: the
      // simpler effect that came close to it in its round, which, refitted beside the others once
      // they are in, may say what the member only approximated.
      for (const auto& member : joint->members()) {
        const auto rival = rivals.find(member->name());
        const std::shared_ptr<const Effect> simpler = rival != rivals.end() ? model.effect(rival->second) : nullptr;
        if (!simpler) continue;
        std::vector<std::shared_ptr<const Effect>> effects;
        for (const auto& m : joint->members()) effects.push_back(m->name() == member->name() ? simpler : m);
        const std::optional<JointEffect> swap = joint_of(effects, settings);
        const std::optional<EffectRegistration> swap_registration = swap ? registration_for(*swap, settings) : std::nullopt;
        if (!swap_registration) continue;
        jobs.push_back([&, registration = *swap_registration, joint_cv, swap = *swap,
                        without = model.without_effect(member->name()), name = member->name()](const ParallelFor& rows) {
          CandidateScore score = score_candidate(without, registration, observations, search, base, folds, rows, joint_cv, &swap);
          score.replaces = {name};
          return score;
        });
      }
    }
  }
  std::vector<CandidateScore> ranking = score_side_by_side(jobs, parallel);
  std::stable_sort(ranking.begin(), ranking.end(), [](const CandidateScore& a, const CandidateScore& b) {
    if (a.failure.empty() != b.failure.empty()) return a.failure.empty();
    return a.held_out_rmse_nm < b.held_out_rmse_nm;
  });
  return ranking;
}

}  // namespace gc
