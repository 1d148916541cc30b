#include "diagnosis/verdict_text.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "diagnosis/diagnose.h"
#include "core/engineering_text.h"
#include "core/effects/expression_terms.h"

namespace gc {
namespace {

bool plausible_fit(const CandidateScore& c) { return c.fit && c.fit->plausible(); }

std::string percent(double share) { return std::to_string(static_cast<int>(std::lround(100.0 * share))) + " %"; }

std::string channels(const Eigen::Vector2d& reduction) {
  const bool y = reduction(0) >= 0.25, z = reduction(1) >= 0.25;
  if (y && z) return "Msy' and Msz'";
  if (y) return "Msy'";
  if (z) return "Msz'";
  return reduction(0) >= reduction(1) ? "Msy'" : "Msz'";
}

std::string noise_text(const DiagnosisRound& round) {
  return "RMSE " + engineering_text(round.rmse_nm, "N·m") + " against a noise estimate of " +
         engineering_text(round.noise.pooled_sigma_nm(), "N·m") + " (lag-1 autocorrelation " + short_number(round.noise.phi.maxCoeff()) + ")";
}

/// "c1 [formula1] + c2 [formula2]" with units and standard errors, then the mechanisms.
std::string formula_text(const EffectFit& fit) {
  std::string text, mechanisms;
  for (const ParameterEstimate& p : fit.parameters) {
    const ExpressionTerm* term = find_expression_term(p.name);
    const double reference = std::max(std::abs(p.value), p.standard_error.value_or(0.0));
    text += (text.empty() ? "" : " + ") + engineering_text(p.value, p.unit, reference);
    if (p.standard_error) text += " (+/- " + engineering_text(*p.standard_error, p.unit, reference) + ")";
    text += " x " + (term ? term->formula : p.name) + " [" + p.name + "]";
    if (term) mechanisms += (mechanisms.empty() ? "" : " | ") + p.name + ": " + term->mechanisms;
  }
  return "(M_sy', M_sz') += " + text + ". Such terms usually mean: " + mechanisms;
}

/// When the discrepancy stage's formula does as well as the claimed effect on held-out data (but
/// not so much better that it is claimed instead), it is shown: another reading of the same residual.
/// When it does significantly better, but the effect takes most of what it finds (physics first:
/// DiagnosisSettings::formula_over_effect_gain, effect_explains_part), it is shown as what the next
/// round looks for, never as a reading this data cannot tell from the effect.
std::string rival_formula_text(const DiagnosisRound& round) {
  if (!round.formula || round.formula_chosen || round.ranking.empty() || !round.formula->fit) return "";
  const double t = round.formula_against_effect.t;
  // Within the uncertainty of each other (the effect not better by a block-paired t of 2): say so,
  // as for two library effects.
  if (round.formula->held_out_rmse_nm > round.ranking.front().held_out_rmse_nm && t < -2.0) return "";
  const std::string held_out = "(RMSE " + engineering_text(round.formula->held_out_rmse_nm, "N·m") + ", t = " +
                               short_number(t) + " against the effect)";
  if (t >= 2.0) {
    return " A formula of physical terms does better on held-out data " + held_out +
           "; the effect is claimed first, since it takes most of what the formula finds (physics first), and the "
           "next round looks for the rest: " + formula_text(*round.formula->fit) + ".";
  }
  return " A formula of physical terms does as well on held-out data " + held_out +
         ", another reading of the same residual that this data cannot tell from it: " +
         formula_text(*round.formula->fit) + ".";
}

std::string dropped_text(const DiagnosisRound& round) {
  std::string text;
  const std::vector<std::string>& replaced = round.chosen().replaces;
  for (const std::string& name : round.dropped) {
    if (std::find(replaced.begin(), replaced.end(), name) != replaced.end()) {
      text += " It takes the place of the earlier claim " + name + ", which is dropped: without it, and with these "
              "refitted together, the model predicts the held-out rows as well, with fewer parameters.";
    } else {
      text += " With it in place, the earlier claim " + name + " no longer lowers the held-out error and is dropped.";
    }
  }
  return text;
}

std::string signature_text(const ResidualSignature& signature) {
  std::ostringstream text;
  int shown = 0;
  for (const InputSignature& s : signature.inputs) {
    if (!s.systematic || shown == 2) continue;
    double low_y = INFINITY, high_y = -INFINITY, low_z = INFINITY, high_z = -INFINITY;
    for (const SignatureBin& b : s.bins) {
      low_y = std::min(low_y, b.mean_y_nm); high_y = std::max(high_y, b.mean_y_nm);
      low_z = std::min(low_z, b.mean_z_nm); high_z = std::max(high_z, b.mean_z_nm);
    }
    text << (shown++ ? "; then " : "") << s.input << " (given the other inputs, its bin means carry "
         << percent(s.explained_share) << " of the residual; Msy' " << engineering_range(low_y, high_y, "N·m")
         << ", Msz' " << engineering_range(low_z, high_z, "N·m") << "; trend "
         << engineering_text(s.slope_y, "N·m") << " and " << engineering_text(s.slope_z, "N·m") << " per " << s.unit;
    for (const std::string& other : s.confounded_with) {
      text << "; it moves with " << other << " on this recording, which cannot tell the two apart";
    }
    text << ")";
  }
  return shown ? "systematic against " + text.str() : "no single input shows it";
}

/// Plausibility is advice: a value outside the usual range stays the answer, and the rig is checked.
std::string implausible_advice(const EffectFit& fit) {
  std::string text;
  for (const ParameterEstimate& p : fit.parameters) {
    if (p.held || p.plausible || p.at_bound) continue;
    text += " " + p.name + " is " + p.note + ".";
  }
  if (text.empty()) return "";
  return " It is still the best explanation on held-out data, with a value outside the range this physics usually "
         "has:" + text;
}

std::string gain_text(const DiagnosisRound& round, const CandidateScore& c) {
  return "held-out RMSE falls " + percent(c.reduction) + " (" +
         engineering_text(round.search_base_rmse_nm, "N·m") + " to " +
         engineering_text(c.held_out_rmse_nm, "N·m", round.search_base_rmse_nm) + "; noise " +
         engineering_text(round.noise.pooled_sigma_nm(), "N·m", round.search_base_rmse_nm) + ")";
}

/// "refine friction: the model has it, and with its parameters freed it explains", or, for
/// effects refitted as one ("a+b", core/effects/joint_effect.h), "refit a and b together: ...".
std::string refinement_text(const std::string& name) {
  if (name.find('+') == std::string::npos) return "refine " + name + ": the model has it, and with its parameters freed it explains";
  std::string names = name;
  const std::size_t last = names.rfind('+');
  names.replace(last, 1, " and ");
  for (std::size_t at = names.find('+'); at != std::string::npos; at = names.find('+')) names.replace(at, 1, ", ");
  return "refit " + names + " together: the model has them, each fitted in an earlier round beside what it did not "
         "explain, and with their parameters freed together they explain";
}

}  // namespace

std::string short_number(double value) {
  std::ostringstream text;
  text.precision(3);
  text << value;
  return text.str();
}

std::string fitted_parameters_text(const EffectFit& fit) {
  std::string text;
  for (const ParameterEstimate& p : fit.parameters) {
    const double reference = std::max(std::abs(p.value), p.standard_error.value_or(0.0));
    text += (text.empty() ? "" : ", ") + p.name + " = " + engineering_text(p.value, p.unit, reference);
    if (p.standard_error) text += " (+/- " + engineering_text(*p.standard_error, p.unit, reference) + ")";
    if (p.held) text += " [held: " + p.note + "]";
    else if (!p.note.empty()) text += " [" + p.note + "]";
  }
  return text;
}

std::string round_verdict_body(int number, const DiagnosisRound& round);

std::string round_verdict(int number, const DiagnosisRound& round) {
  const std::string body = round_verdict_body(number, round);
  return round.mains_pickup.empty() ? body : body + " Besides: " + round.mains_pickup + ".";
}

std::string round_verdict_body(int number, const DiagnosisRound& round) {
  std::string model;
  for (const std::string& e : round.model_effects) model += (model.empty() ? "" : ", ") + e;
  const std::string head = "Round " + std::to_string(number) + " (model: " + (model.empty() ? "no effects" : model) + "): ";
  switch (round.outcome) {
    case RoundOutcome::noise:
      if (round.unstructured_excess) {
        return head + "the residual is noise: " + noise_text(round) + " (its own scale: a short variogram put it lower, "
               "but no input, time pattern or frequency explains enough of the difference on held-out data to be "
               "claimed; noise with heavy tails, a long correlation or a wandering level, not physics). No effect is "
               "claimed.";
      }
      return head + "the residual is noise: " + noise_text(round) +
             ", and no input shows a systematic dependence. No effect is claimed.";
    case RoundOutcome::unexplained: {
      std::string best;
 if (!round.ranking.empty() && round.ranking.front().failure.empty()) {
        best = " (the best, " + round.ranking.front().info->name + ", lowers the held-out RMSE by " +
               percent(round.ranking.front().reduction) + " with t = " + short_number(round.ranking.front().against_base.t) +
               " over blocks of the recording; a claim needs t >= 3.5, 5 % of the mean square and 30 % of the excess "
               "over the noise)";
      }
      if (round.signature_reduction) {
        best += "; the signature's additive model of the inputs lowers it by " + percent(*round.signature_reduction) +
                " on held-out blocks";
      }
 return head + "the residual is systematic (" + noise_text(round) + ") but neither an effect of the library nor a formula of physical terms explains it" +
             best + ". Its signature: " + signature_text(round.signature) + ".";
    }
    case RoundOutcome::effect_found: {
      const CandidateScore& c = round.ranking.front();
      if (c.kind == CandidateKind::refinement) {
        return head + refinement_text(c.info->name) + " the residual in " +
               channels(round.channel_reduction) + " (" + c.info->physics + "): " + fitted_parameters_text(*round.claimed) +
               "; " + gain_text(round, c) + "." + rival_formula_text(round) + dropped_text(round);
      }
      return head + "the residual in " + channels(round.channel_reduction) + " is explained by " + c.info->name +
             " (" + c.info->physics + "): " + fitted_parameters_text(*round.claimed) + "; " + gain_text(round, c) + "." +
             implausible_advice(*round.claimed) + rival_formula_text(round) + dropped_text(round);
    }
    case RoundOutcome::partly_explained: {
      const CandidateScore& c = round.ranking.front();
      const std::string rival = rival_formula_text(round);  // a formula that does as well or better, if any
      return head + (c.kind == CandidateKind::refinement ? "refining " : "") + c.info->name + " partly explains the residual in " +
             channels(round.channel_reduction) + " (" + c.info->physics + "): " + fitted_parameters_text(*round.claimed) + "; " +
             gain_text(round, c) + ". Only partly: " + round.partly_reason + (rival.empty() ? "; no formula did better" : "") +
             ". The search continues with it." + rival + dropped_text(round);
    }
    case RoundOutcome::formula_proposed: {
      const CandidateScore& c = *round.formula;
      std::string effect;
      if (!round.ranking.empty() && round.ranking.front().failure.empty()) {
        const CandidateScore& e = round.ranking.front();
        effect = " (the best effect, " + std::string(e.kind == CandidateKind::refinement ? "refining " : "") + e.info->name +
                 ", lowers it " + percent(e.reduction) + (plausible_fit(e) ? "" : " with implausible values");
        if (round.formula_simpler_and_better) {
          const std::size_t terms = fitted_parameter_count(c);
          effect += ", and could be claimed; the formula, with " + std::to_string(terms) +
                    (terms == 1 ? " parameter" : " parameters") + " against its " +
                    std::to_string(fitted_parameter_count(e)) + ", predicts the held-out rows better, t = " +
                    short_number(round.formula_against_effect.t) + ", on whole fifths too";
        }
        effect += ")";
      }
      const std::string where =
          round.formula_on_dense_rows ? " (found on the recording's dense rows: too weak for the search rows)" : "";
      const std::string residual = "the residual in " + channels(round.channel_reduction);
      const std::string lead = round.formula_simpler_and_better
                                   ? "a formula explains " + residual + " better than any effect of the library" + effect +
                                         where + ": "
                                   : "no effect of the library explains " + residual + effect + "; a formula does" + where + ": ";
      return head + lead + formula_text(*round.claimed) + ". " + gain_text(round, c) +
             ". The search continues with it (an expression effect in the model file)." + dropped_text(round);
    }
    case RoundOutcome::indistinguishable: {
      const CandidateScore& c = round.ranking.front();
      std::string text = head + c.info->name;
      for (const AlikeEffect& a : round.alike) text += " and " + a.name;
      text += " explain the residual in " + channels(round.channel_reduction) + " equally on this data (" + c.info->name +
              ": " + gain_text(round, c);
      for (const AlikeEffect& a : round.alike) {
        text += "; " + a.name + ": corrections correlated r = " + short_number(a.correlation) +
                ", difference t = " + short_number(a.against_best.t) + "); to tell " + c.info->name + " from " + a.name +
                ", " + a.experiment.advice;
      }
      return text + ". The search continues with " + c.info->name + ": " + fitted_parameters_text(*round.claimed) + "." +
             dropped_text(round);
    }
  }
  return head;
}

}  // namespace gc
