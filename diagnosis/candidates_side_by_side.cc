#include "diagnosis/candidates_side_by_side.h"

#include <atomic>

namespace gc {

std::vector<CandidateScore> score_side_by_side(const std::vector<CandidateJob>& jobs, const ParallelFor& parallel) {
  std::vector<CandidateScore> scores(jobs.size());
  std::atomic<std::size_t> next{0};
  const ParallelFor serial = serial_for();
  // The ParallelFor deals the range out in fixed chunks; each chunk ignores its share and takes
  // jobs from the common counter instead, so a worker that drew cheap candidates takes more.
  parallel(jobs.size(), [&](std::size_t, std::size_t) {
    for (std::size_t k = next++; k < jobs.size(); k = next++) scores[k] = jobs[k](serial);
  });
  return scores;
}

}  // namespace gc
