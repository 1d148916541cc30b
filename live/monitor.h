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
#include "protocol/dds_entity.h"

namespace gc::live {

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
  /// first time and then at most once a minute; a cell's place is free again once disposed
  /// (dispose_s). A cell costs 41 kB resident (its CellMonitor: two health windows, the model
  /// in force and the one before; Cyclone's instances; docs/dashboard.md, "Bounds"), so 64, a
  /// test hall, keep the monitor within 3 MB whatever names arrive. What swaps leave per test
  /// cell (model, decimation, refusal) is kept for at most 2 max_cells cells (make_room).
  std::size_t max_cells = 64;
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
  std::uint64_t refused_batches() const { return refused_batches_; }
  /// Measurement batches and model swaps refused because their writer's partition is another
  /// test cell's (a cell identity speaking for a cell it is not granted).
  std::uint64_t refused_foreign() const { return refused_foreign_; }

 private:
  struct Cell;
  void take_models();
  void take_measurements();
  void publish_health();
  /// `test_cell`'s state, made when new; nullptr when max_cells cells are followed and it is
  /// not configured (counted and logged by refuse_cell).
  Cell* cell(const std::string& test_cell);
  void refuse_cell(const std::string& test_cell, std::size_t samples);
  /// Whether the writer of a sample of `reader` (its publication_handle) may speak for
  /// `test_cell` (partitions_speak_for); logs and counts a refusal (`what`: "measurement batch").
  bool from_own_partition(dds_entity_t reader, dds_instance_handle_t publication,
                          const std::string& test_cell, const char* what);
  /// Subscription-matched listener: learns a writer's partitions while it is surely matched,
  /// before its first sample is taken (it may be gone by then: a short run).
  void remember_writer(dds_entity_t reader, dds_instance_handle_t publication);
  /// Makes room in `kept` (what swaps left, by test cell) for `test_cell`: at most
  /// 2 max_cells + the configured cells are kept, so once full what is kept for a cell neither
  /// followed nor configured is dropped (logged once). False only if there is none to drop.
  template <typename Map>
  bool make_room(Map& kept, const std::string& test_cell);
  CellModel model_for(const std::string& test_cell);
  /// The model of a swap's text, parsed once (throws InvalidInput as parse_cell_model).
  CellModel parsed_model(const std::string& text, const std::string& test_cell);

  MonitorOptions options_;
  std::uint64_t monitor_id_;
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
  protocol::Entity waitset_;
  std::atomic<bool> stopping_{false};
  std::uint64_t refused_batches_ = 0, refused_samples_ = 0, dropped_swaps_ = 0;
  std::uint64_t refused_batches_logged_ = 0;
  std::uint64_t refused_foreign_ = 0;
  /// Writers' partitions by publication handle (never reused by Cyclone): learnt when a writer
  /// matches (remember_writer, in Cyclone's thread), so one DDS query per writer; emptied at
  /// 4096 entries (then asked again while the writer is matched).
  std::mutex writer_partitions_mutex_;
  std::map<dds_instance_handle_t, std::vector<std::string>> writer_partitions_;
  std::chrono::steady_clock::time_point refusals_logged_at_{};
};

}  // namespace gc::live
