// gearcoupling-monitor's work over DDS (docs/architecture.md, "The live test cell"): reads the
// measurement and model topics, keeps one CellMonitor per test cell, writes residuals after
// each batch and every cell's health once per health period. One thread: a model swap is taken
// between two measurement batches, so no sample is lost or evaluated twice across it.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "live/cell_monitor.h"
#include "live/diagnosis_worker.h"
#include "live/learning_status.h"
#include "live/monitor_status_wire.h"
#include "live/refusal_log.h"
#include "live/swap_audit.h"
#include "protocol/dds_entity.h"

namespace gc::live {

/// The learning loop (docs/architecture.md, "The learning loop"): when a test cell's error stays
/// beyond the noise, the monitor diagnoses its rolling window in the background and proposes a
/// model (live/diagnosis_worker.h, live/proposal.h).
struct LearningOptions {
  bool enabled = true;
  /// A cell's health must show an error beyond the noise (either channel) for this long, wall
  /// clock, before its first diagnosis [s].
  double diagnose_after_s = 10.0;
  double rediagnose_s = 60.0;   ///< a cell's next diagnosis no sooner after the last [s]
  double recheck_s = 30.0;      ///< a standing proposal is rechecked on newer samples this often [s]
  std::size_t queue = 4;        ///< diagnoses waiting at most (one runs at a time)
  int nice = 19;                ///< the diagnosis thread's nice value, 0 to 19
  /// The diagnosis thread's CPU at most, as a share of one core (it sleeps between its loops of
  /// model evaluations in proportion to their CPU time): 0.25 keeps 3/4 of a core for the
  /// monitor's thread and the rest of the host whatever the scheduler does with nice values
  /// (with autogroup, a thread's nice matters only against its own process's threads).
  double cpu_share = 0.25;
};

/// Who swapped a model and from what: the swap writer's USER_DATA ("by=NAME;source=..." as
/// gearcoupling swap-model and the dashboard set it, NAME the person: live/swap_operator.h), else
/// its participant's GUID; the writer's GUID; and the
/// operator identity of its partitions (operator_identity_of), which DDS Security authenticates.
struct SwapOrigin {
  std::string by, source, writer, operator_identity;
};
SwapOrigin swap_origin(dds_entity_t reader, dds_instance_handle_t publication);

struct MonitorOptions {
  std::uint32_t domain = 0;
  std::string default_model = "paper";            ///< for test cells not in cell_models
  std::map<std::string, std::string> cell_models; ///< test cell -> model file or bundled name
  std::filesystem::path models_dir;               ///< where bundled model names are looked up
  std::filesystem::path catalog_dir;              ///< the coupling catalogue
  CellMonitorOptions cell;
  double health_period_s = 1.0;   ///< [s]
  double stale_s = 2.0;           ///< health says stale after this long without a sample [s]
  double dispose_s = 10.0;        ///< and the cell's health is disposed after this long [s]
  std::uint32_t decimation = 1;   ///< residuals: one per this many evaluated samples
  /// Test cells followed at once, besides those named in cell_models (always followed). A
  /// batch of a new test cell beyond it is refused and counted (refused_batches()), logged the
  /// first time and then summarised at most once a second (RefusalLog); a cell's place is free again once disposed
  /// (dispose_s). A cell costs 41 kB resident (its CellMonitor: two health windows, the model
  /// in force and the one before; Cyclone's instances; docs/dashboard.md, "Bounds"), so 64, a
  /// test hall, keep the monitor within 3 MB whatever names arrive; plus, for a cell that
  /// streams, its diagnosis window (at most cell.diagnosis_samples x 192 B: 384 kB at the
  /// default 2000, 25 MB for 64 streaming cells) and the copies queued for the diagnosis (at
  /// most learning.queue + 1 windows). What swaps leave per test
  /// cell (model, decimation, refusal) is kept for at most 2 max_cells cells (make_room).
  std::size_t max_cells = 64;
  LearningOptions learning;
  /// Where the audit trail of model swaps is kept across restarts (live/swap_audit_file.h); ""
  /// keeps it in memory only.
  std::filesystem::path state_dir;
};

class Monitor {
 public:
  /// Loads every configured model (throws InvalidInput naming the file and field) and creates
  /// the DDS entities.
  explicit Monitor(const MonitorOptions& options);
  ~Monitor();

  /// Serves until stop() is called.
  void run();
  /// Thread-safe; not async-signal-safe (call it from a thread that waited for the signal).
  void stop();

  std::uint64_t monitor_id() const { return monitor_id_; }
  /// Measurement batches refused because max_cells test cells were followed.
  std::uint64_t refused_batches() const { return refusals_.count(Refusal::batch_beyond_max_cells); }
  /// Measurement batches and model swaps refused because their writer's partition is another
  /// test cell's (a cell identity speaking for a cell it is not granted).
  std::uint64_t refused_foreign() const {
    return refusals_.count(Refusal::batch_foreign) + refusals_.count(Refusal::swap_foreign);
  }

 private:
  struct Cell;
  void take_models();
  void take_measurements();
  void publish_health();
  /// Submits a diagnosis of `cell`, or a recheck of its standing proposal, when due.
  void learn(const std::string& test_cell, Cell& cell, const HealthReport& health, bool stale);
  /// What the learning loop does for `cell` and waits for (after learn), logged when it changes.
  LearningStatus learning_of(const std::string& test_cell, Cell& cell, const HealthReport& health,
                             bool stale);
  /// Publishes what the worker found (on the monitor's thread).
  void take_outcomes();
  void take_outcome(DiagnosisOutcome outcome);
  /// The swap of `test_cell` to `model` (already in force), in the audit trail and in the
  /// state of the cell's proposal.
  void audit_swap(const std::string& test_cell, Cell* cell, const CellModel& model,
                  const std::string& text, const SwapOrigin& origin, std::int64_t written_ns);
  void publish_proposal(Cell& cell);
  MonitorCounters counters() const;
  /// `test_cell`'s state, made when new; nullptr when max_cells cells are followed and it is
  /// not configured (counted and logged by refuse_cell).
  Cell* cell(const std::string& test_cell);
  void refuse_cell(const std::string& test_cell, std::size_t samples);
  /// Whether the writer of a sample of `reader` (its publication_handle) may speak for
  /// `test_cell` (partitions_speak_for); logs and counts a refusal of `kind` (`what`:
  /// "measurement batch").
  bool from_own_partition(dds_entity_t reader, dds_instance_handle_t publication,
                          const std::string& test_cell, Refusal kind, const char* what);
  /// The partitions of the writer of a sample of `reader` (learnt at its match, else asked now);
  /// empty when it is gone.
  std::vector<std::string> partitions_of(dds_entity_t reader, dds_instance_handle_t publication);
  /// Subscription-matched listener: learns a writer's partitions while it is surely matched,
  /// before its first sample is taken (it may be gone by then: a short run).
  void remember_writer(dds_entity_t reader, dds_instance_handle_t publication);
  /// Makes room in `kept` (what swaps left, by test cell) for `test_cell`: at most
  /// 2 max_cells + the configured cells are kept, so once full what is kept for a cell neither
  /// followed nor configured is dropped (logged once). False only if there is none to drop.
  template <typename Map>
  bool make_room(Map& kept, const std::string& test_cell);
  CellModel model_for(const std::string& test_cell);
  /// A swap for `test_cell` that did not load: counted, logged (rate-limited), and its reason
  /// (printable, at most kMaxRefusalBytes) told in the cell's health; the model in force stays.
  void refuse_model(const std::string& test_cell, const std::exception& error);
  static constexpr std::size_t kMaxRefusalBytes = 512;
  /// The model of a swap's text, parsed once (throws InvalidInput as parse_cell_model).
  CellModel parsed_model(const std::string& text, const std::string& test_cell);

  MonitorOptions options_;
  std::uint64_t monitor_id_;
  SwapAudit audit_;   // first: a bad --state-dir is refused before DDS is touched
  CellModel default_model_;
  std::map<std::string, CellModel> models_;       // configured, or swapped in while absent
  std::map<std::string, std::uint32_t> decimations_;
  std::map<std::string, std::string> model_refusals_;   // for test cells not seen yet
  // Models parsed from swap texts, by text: a dashboard switching between before and after
  // sends the same few texts again and again, and parsing one builds a whole coupling.
  std::map<std::string, CellModel> parsed_models_;
  static constexpr std::size_t kParsedModelsKept = 16;
  std::map<std::string, std::unique_ptr<Cell>> cells_;
  protocol::Entity participant_;
  protocol::Entity subscriber_, publisher_;
  protocol::Entity measurement_topic_, residual_topic_, health_topic_, model_topic_;
  protocol::Entity measurement_reader_, model_reader_, residual_writer_, health_writer_;
  protocol::Entity proposal_topic_, monitor_topic_, proposal_writer_, monitor_writer_;
  protocol::Entity waitset_;
  protocol::Entity outcomes_ready_;   // guard condition: the worker finished a job
  std::atomic<bool> stopping_{false};
  RefusalLog refusals_;   // every refusal counted by kind, the log rate-limited
  std::uint64_t dropped_swaps_ = 0;
  /// Writers' partitions by publication handle (never reused by Cyclone): learnt when a writer
  /// matches (remember_writer, in Cyclone's thread), so one DDS query per writer; emptied at
  /// 4096 entries (then asked again while the writer is matched).
  std::mutex writer_partitions_mutex_;
  std::map<dds_instance_handle_t, std::vector<std::string>> writer_partitions_;
  std::uint64_t proposals_published_ = 0, proposals_withdrawn_ = 0;
  std::uint64_t diagnoses_run_ = 0, diagnoses_dropped_ = 0;
  std::uint64_t next_generation_ = 1;
  std::unique_ptr<DiagnosisWorker> worker_;   // last: stopped first, before what it wakes
};

}  // namespace gc::live
