// Which of an implausible candidate ranked first and the best plausible one the round claims,
// judged against noise with the recording's spectrum (surrogate_test.h).
//
// put_claim_first (claim_order.h) keeps an implausible candidate first when it is significantly
// better on held-out blocks. Interleaved blocks cannot see noise as slow as the recording: a
// channel gain and offset (4 parameters, gains outside their plausible range) took 40 % of a
// brown noise's variance beside a true compliance (1 parameter), held out 4.4 kN·m against 5.0,
// t = 7.9. What the implausible candidate explains beyond the plausible one must be more than
// noise like what the plausible one leaves would give it.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "core/recorded_sample.h"
#include "diagnosis/candidate_score.h"
#include "diagnosis/parallel_for.h"
#include "diagnosis/surrogate_claims.h"

namespace gc {

/// When `ranking`'s first is claimable but implausible and a later claimable one, with no failure,
/// is plausible: moves the plausible one first unless the first's design explains what the
/// plausible one leaves of `base` (on `rows`) better than surrogates of it, at `settings.level`.
/// Candidates that refit or replace earlier claims are left where they are.
void put_plausible_first_unless_beyond_noise(
    std::vector<CandidateScore>& ranking, const CouplingModel& model, std::span<const RecordedSample> observations,
    std::span<const std::size_t> rows, const Eigen::MatrixX2d& base, const ParallelFor& parallel,
    const std::function<bool(const CandidateScore&)>& claimable,
    const std::function<std::optional<EffectRegistration>(const Effect&)>& registration_for,
    const SurrogateClaimSettings& settings);

}  // namespace gc
