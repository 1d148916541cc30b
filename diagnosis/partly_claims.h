// Claims a round said explain only partly. Fitted one after the other, effects trade with each
// other; the effects earlier rounds added are refitted together once one of them is only partly
// right, with a simpler rival of the model in a member's place when one came close in its round.
#pragma once

#include <optional>
#include <set>
#include <string>

#include "core/coupling_model.h"
#include "core/effects/joint_effect.h"
#include "diagnosis/candidate_score.h"
#include "diagnosis/diagnose.h"

namespace gc {

/// The effects earlier rounds added (the formula aside), as one effect to refit jointly, when
/// there are two or more and one of them was said to explain only partly: fitted one after the
/// other they trade with each other (a thermal misalignment fitted beside a weight offset that
/// the next round explained took a share of it, and refitting each in turn creeps toward the
/// truth a round at a time). The latest three: a fit of more parameters costs more than it finds.
std::optional<JointEffect> partly_claims_together(const CouplingModel& model, const CouplingModel& given,
                                                  const std::set<std::string>& partly, const DiagnosisSettings& settings);

/// The fit of a joint refit: the parameters of two or three effects, some of which trade with
/// each other (a thermal growth g and its reference temperature theta_0 along a valley), so more
/// probes, starts and steps than one effect's. From round 1's g = -18.7 µrad/degC at 17.5 degC the
/// default 8 probes, 2 starts and 10 steps stopped at -29 µrad/degC (2.66 kN·m held out); with
/// these, at the truth's 59-62 µrad/degC at 35 degC (1.95 kN·m).
CrossValidationSettings joint_refit_settings(CrossValidationSettings settings);

/// A partly claim's rival: an effect of the given model whose refinement came within this share
/// of the claim's held-out RMSE in the claim's round, with fewer parameters. A round that says
/// "partly" ranks what the residual still held beside its own effect: a channel gain and offset
/// (four parameters) took a heavier self-weight (one) with a gain that soaked up a thermal
/// misalignment fitted before it, 3.69 against 3.88 kN·m.
constexpr double kRivalShare = 0.1;

/// The rival of the round's partly claim (kRivalShare), if any: the effect's name.
std::optional<std::string> rival_of_claim(const DiagnosisRound& round, const CouplingModel& given);

}  // namespace gc
