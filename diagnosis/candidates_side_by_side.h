// Candidates scored side by side. A candidate's score is a long chain of model evaluations
// (starts, Levenberg-Marquardt steps, polish, folds), each of which the rows' ParallelFor splits
// into a short parallel section that waits for its slowest part, thousands of times a round. The
// candidates themselves are independent: one whole candidate per worker keeps the cores busy
// between evaluations, and a loaded machine slows one candidate, not every evaluation.
#pragma once

#include <functional>
#include <vector>

#include "diagnosis/candidate_score.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// Scores one candidate; `rows` is the ParallelFor for its model evaluations.
using CandidateJob = std::function<CandidateScore(const ParallelFor& rows)>;

/// Every job's score, in the jobs' order. Each job runs whole on one of `parallel`'s workers with a
/// serial ParallelFor, the workers taking the next job as they free up; the scores are those of
/// the jobs run one after the other (each is deterministic and shares nothing mutable).
std::vector<CandidateScore> score_side_by_side(const std::vector<CandidateJob>& jobs, const ParallelFor& parallel);

}  // namespace gc
