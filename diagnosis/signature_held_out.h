// The residual's signature held out: does the structure the signature sees in the inputs predict
// rows it was not fitted on? An "unexplained" verdict claims structure as surely as an effect does,
// so it pays the same held-out test (docs/diagnosis.md, "The claim rule"): on noise the signature's
// F tests, which judge bins of neighbouring samples, called 9 of 40 recordings of a noise zoo
// "unexplained" while the best candidate cut 0-3.6 %.
#pragma once

#include <optional>
#include <span>

#include <Eigen/Dense>

#include "diagnosis/candidate_score.h"
#include "diagnosis/cross_validation_folds.h"
#include "diagnosis/residual_signature.h"
#include "diagnosis/surrogate_test.h"
#include "core/recorded_sample.h"

namespace gc {

/// The additive model of the signature's systematic inputs (time aside: a wander in time is the
/// noise's as much as anything, and interleaved folds would let it predict its neighbours), one
/// level per bin as residual_signature cuts them, fitted by least squares on each fold's training
/// rows and scored on its held-out rows against `base` (the model's residual on `rows`). nullopt
/// when no such input is systematic. The score's kind is `formula` and its fit is empty.
std::optional<CandidateScore> signature_held_out(std::span<const RecordedSample> observations,
                                                 std::span<const std::size_t> rows, const Eigen::MatrixX2d& base,
                                                 const Folds& folds, const ResidualSignature& signature);

/// The same additive model as a design for the surrogate test (surrogate_test.h), both channels
/// stacked with their own bin levels: an "unexplained" verdict pays the third test of the claim
/// rule as an effect does. nullopt when no such input is systematic.
std::optional<SurrogateDesign> signature_design(std::span<const RecordedSample> observations,
                                               std::span<const std::size_t> rows, const ResidualSignature& signature);

}  // namespace gc
