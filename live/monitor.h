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
#include <string>

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

 private:
  struct Cell;
  void take_models();
  void take_measurements();
  void publish_health();
  Cell& cell(const std::string& test_cell);
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
};

}  // namespace gc::live
