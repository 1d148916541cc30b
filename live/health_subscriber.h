// Reads the monitor's health (CellHealth) and residuals (ResidualBatch) as any dashboard would:
// the latest health of every test cell, whether it is alive, and every residual received.
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "protocol/dds_entity.h"

namespace gc::live {

/// One CellHealth sample, in C++ types (members as the IDL's).
struct HealthView {
  std::string test_cell;
  bool stale = false;
  bool disposed = false;           ///< the monitor disposed the cell (or the monitor left)
  double window_begin_s = 0.0, window_end_s = 0.0;
  std::uint64_t window_samples = 0;
  std::string model_name;
  double model_since_unix_s = 0.0, model_in_force_s = 0.0;
  std::uint64_t model_evaluated = 0;
  double rmse_nm[2] = {}, bias_nm[2] = {}, noise_nm[2] = {}, systematic_nm[2] = {};
  bool at_noise_level[2] = {};
  std::optional<std::string> previous_model_name;
  double previous_rmse_nm[2] = {};
  std::string worst_region, last_refusal, last_model_refusal;
  std::uint64_t taken = 0, evaluated = 0, refused_not_finite = 0, refused_by_model = 0,
                refused_out_of_order = 0, lost = 0, runs = 0;
};

class HealthSubscriber {
 public:
  explicit HealthSubscriber(dds_entity_t participant);
  /// Takes what arrived; returns the latest health of `test_cell` (nullopt before any).
  std::optional<HealthView> latest(const std::string& test_cell);
  /// Polls until `ready` holds for test_cell's latest health or `timeout` passes.
  std::optional<HealthView> wait_for(const std::string& test_cell,
                                     const std::function<bool(const HealthView&)>& ready,
                                     std::chrono::milliseconds timeout);

 private:
  void take();
  protocol::Entity subscriber_, topic_, reader_;
  std::map<std::string, HealthView> latest_;
};

}  // namespace gc::live
