#include "diagnosis/claim_refit.h"

#include <algorithm>
#include <cmath>

#include "core/effects/expression.h"
#include "diagnosis/claimed_effects.h"
#include "diagnosis/formula_search.h"
#include "diagnosis/model_residuals.h"
#include "diagnosis/row_selection.h"

namespace gc {

std::optional<EffectFit> refit_claim(const CouplingModel& model, const DiagnosisRound& round,
                                     std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                                     const Eigen::MatrixX2d& residual, const std::vector<std::size_t>& refit,
                                     const ParallelFor& parallel, const DiagnosisSettings& settings) {
  const CandidateScore& chosen = round.chosen();
  if (round.formula_chosen) {
    std::vector<std::string> terms;
    for (const ParameterEstimate& p : chosen.fit->parameters) terms.push_back(p.name);
    const std::shared_ptr<const Effect> earlier = model.effect(kExpressionEffect);
    if (!earlier) return fit_formula(observations, refit, select_rows(residual, rows, refit), terms, round.noise.variance_inflation());
    // A model with a formula already gets one formula over both sets of terms, refitted together on
    // what the model leaves without it: a second expression would replace the first.
    for (const ParameterSpec& p : earlier->info().parameters) {
      if (std::find(terms.begin(), terms.end(), p.name) == terms.end()) terms.push_back(p.name);
    }
    const ModelResiduals without = model_residuals(model.without_effect(kExpressionEffect), observations, refit, parallel);
    if (!without.failed_rows.empty()) return std::nullopt;
    return fit_formula(observations, refit, without.residual, terms, round.noise.variance_inflation());
  }
  CouplingModel base = model;
  for (const std::string& name : chosen.replaces) base = base.without_effect(name);
  const std::shared_ptr<const Effect> current = base.effect(chosen.info->name);
  const std::optional<EffectRegistration> registration =
      current ? registration_for(*current, settings) : registration_for(*chosen.fit->effect, settings);
  if (!registration) return std::nullopt;
  std::optional<EffectFit> fit =
      refit_effect(base, *registration, *chosen.fit, observations, refit, parallel, settings.final_iterations, true);
  // s^2 (J'J)^-1 counts every sample as independent; correlated noise carries fewer.
  const double inflation = std::sqrt(round.noise.variance_inflation());
  if (fit) for (ParameterEstimate& p : fit->parameters) if (p.standard_error) *p.standard_error *= inflation;
  return fit;
}

}  // namespace gc
