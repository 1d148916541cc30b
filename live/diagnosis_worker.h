// The monitor's diagnoses, off the hot path: one background thread at a bounded CPU share (after
// each loop of model evaluations it sleeps in proportion to the CPU the loop took: a share of 0.25
// runs 1 ms in 4) and a low priority (its own nice value; 19, the default, is SCHED_IDLE:
// live/background_priority.h), one diagnosis at a time across all test cells, a bounded queue of
// at most one job per test cell. The monitor's thread submits jobs and takes the outcomes; it
// never waits for a diagnosis (docs/architecture.md, "The learning loop").
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "diagnosis/parallel_for.h"
#include "core/recorded_sample.h"
#include "live/cell_model.h"
#include "live/proposal.h"

namespace gc::live {

struct DiagnosisJob {
  std::string test_cell;
  std::uint64_t cell_generation = 0;   ///< the cell's incarnation: a cell gone and back is new
  CellModel base;                      ///< the model in force when the job was made
  std::vector<RecordedSample> samples; ///< the cell's rolling window
  /// Set: a recheck of this standing proposal on newer samples, not a diagnosis.
  std::optional<Proposal> recheck;
};

struct DiagnosisOutcome {
  std::string test_cell;
  std::uint64_t cell_generation = 0;
  CellModel base;
  std::optional<Proposal> proposal;    ///< a diagnosis that found something (id left 0)
  /// A recheck: the proposal it rechecked, and both models' RMSE on the newer samples [N·m].
  std::optional<Proposal> rechecked;
  std::optional<double> base_rmse_nm, proposed_rmse_nm;
  std::string note;                    ///< what it found when no proposal, or its error
  double cpu_s = 0.0;                  ///< CPU time of the job's thread [s]
  std::size_t samples = 0;             ///< in the job's window
};

class DiagnosisWorker {
 public:
  /// `queue` >= 1 jobs waiting at most; the thread runs at nice `nice` (0 to 19; lower_this_thread) and uses at most
  /// `cpu_share` (0 < share <= 1) of a core over each loop; `done` is called from the worker
  /// thread after each outcome is ready (e.g. to wake the monitor's waitset).
  DiagnosisWorker(std::size_t queue, int nice, double cpu_share, std::function<void()> done);
  /// Stops the running job at its next loop of model evaluations (a diagnosis takes seconds; its
  /// loops milliseconds) and drops the queued ones.
  ~DiagnosisWorker();
  DiagnosisWorker(const DiagnosisWorker&) = delete;
  DiagnosisWorker& operator=(const DiagnosisWorker&) = delete;

  /// Queues `job`; false when the queue is full or that test cell has a job queued or running.
  bool submit(DiagnosisJob job);
  /// Whether `test_cell` has a job queued or running.
  bool busy(const std::string& test_cell);
  /// The test cell whose job runs now, "" when idle.
  std::string running();
  /// The outcomes ready since the last call.
  std::vector<DiagnosisOutcome> take_outcomes();

 private:
  void run();

  /// The diagnosis' loops: serial, each followed by a sleep that keeps the thread within
  /// cpu_share_, cancelled (an exception) once the worker stops.
  void throttled_loop(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body);

  std::size_t queue_limit_;
  int nice_;
  double cpu_share_;
  std::function<void()> done_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<DiagnosisJob> queue_;
  std::string running_;                 // test cell of the job running, "" when idle
  std::vector<DiagnosisOutcome> outcomes_;
  bool stopping_ = false;
  std::atomic<bool> cancel_{false};     // read by the running diagnosis' loops
  std::thread thread_;                  // last: started when the rest is ready
};

/// Runs `job` on the calling thread (what the worker does with it), the diagnosis' loops through
/// `parallel`.
DiagnosisOutcome run_job(const DiagnosisJob& job, const ParallelFor& parallel = serial_for());

}  // namespace gc::live
