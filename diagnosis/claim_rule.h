// The claim rule's first test (docs/diagnosis.md, "The claim rule"), and what a candidate's fit says
// beside it: plausible values, or a parameter held on a physical bound.
#pragma once

#include "diagnosis/candidate_score.h"
#include "diagnosis/diagnose.h"

namespace gc {

/// The claim rule (docs/diagnosis.md, "The claim rule"): significant on held-out blocks (a paired t
/// against the long-run variance of the block means), and a material fall of the held-out mean
/// square: a share of the excess over the noise, and a share of the mean square itself.
bool claimable(const CandidateScore& c, double base_ms, double noise_ms, const DiagnosisSettings& settings);

/// The candidate was fitted, with values in their plausible ranges.
bool plausible(const CandidateScore& c);

/// A parameter on a physical bound: the truth may lie beyond what the effect can say.
bool at_bound(const CandidateScore& c);

}  // namespace gc
