// The claim rule's third test (docs/diagnosis.md, "The claim rule"): what noise with the residual's
// own spectrum explains as well is no claim (surrogate_test.h). Applied to every candidate that
// would otherwise be claimable, as one family, so that the chance of any claim on such noise is at
// most the level, whichever candidate the search would take.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "diagnosis/candidate_score.h"
#include "diagnosis/parallel_for.h"
#include "diagnosis/prewhitening.h"
#include "diagnosis/surrogate_test.h"
#include "core/effects/effect_registry.h"
#include "core/recorded_sample.h"

namespace gc {

/// An effect's design on `rows` (surrogate_test.h): its correction at the fit, and how the model's
/// prediction moves with each fitted parameter there (forward differences, a thousandth of the
/// parameter's search box, stepped inward at a bound). Nullopt when a row cannot be predicted.
std::optional<SurrogateDesign> effect_design(const CandidateScore& candidate, const EffectRegistration& registration,
                                             const CouplingModel& model, std::span<const RecordedSample> observations,
                                             std::span<const std::size_t> rows, const Eigen::MatrixX2d& base,
                                             const ParallelFor& parallel);

/// The residual's own filter for the surrogate test's second statistic (Prewhitening::fitted of
/// `base`, the residual on `rows`), marked where the inputs' noise carried through `model` would
/// show in it (exposes_input_noise); the identity where `base` is white.
Prewhitening surrogate_filter(const CouplingModel& model, std::span<const RecordedSample> observations,
                              std::span<const std::size_t> rows, const Eigen::MatrixX2d& base);

struct SurrogateClaimSettings {
  /// Family-wise: the most a claim on such noise may be made, per round (0: the test is not made).
  double level = 0.01;
  std::uint64_t seed = 0x5eed'5u;
};

/// Marks failed (the reason in CandidateScore::failure) each of `ranking`'s candidates for which
/// `claimable` holds, and the formula, when noise with `base`'s spectrum is explained as well, and
/// moves the failed effects last. A refit of several effects or a swap refits earlier claims and
/// is not tested again. `registration_for` gives an effect's registration; the formula's design is
/// the term catalogue on `rows` with `time_terms` and its own terms, its term count chosen greedily.
/// The family is every candidate of `ranking`, the formula and `also_tried` more (the round's
/// other searches).
void demote_what_noise_explains(
    std::vector<CandidateScore>& ranking, std::optional<CandidateScore>& formula,
    const std::vector<std::string>& time_terms, const CouplingModel& model,
    std::span<const RecordedSample> observations, std::span<const std::size_t> rows, const Eigen::MatrixX2d& base,
    const ParallelFor& parallel, const std::function<bool(const CandidateScore&)>& claimable,
    const std::function<std::optional<EffectRegistration>(const Effect&)>& registration_for,
    const SurrogateClaimSettings& settings, std::size_t also_tried = 0);

}  // namespace gc
