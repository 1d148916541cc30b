// One test cell's latest health (gearcoupling/live/health) as flat C++ values, for code that
// checks numbers: `gearcoupling swap-model`, the live tests and benchmarks. Read by CellBoard
// (cell_board.h), the one reader of the health topic; this is a view of its record.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "clients/status/model_health.h"
#include "idl/live_status.pb.h"

namespace gc::status {

/// A CellHealth sample's members (as the IDL's, texts cut at kMaxTextBytes) with the board's
/// state of the cell.
struct HealthView {
  std::string test_cell;
  bool stale = false;     ///< the board's "stale": the monitor says so, its health is late,
                          ///< or its writer's liveliness lapsed
  bool disposed = false;  ///< the board's "gone": the monitor disposed the cell
  double window_begin_s = 0.0, window_end_s = 0.0;
  std::uint64_t window_samples = 0;
  std::string model_name;
  double model_since_unix_s = 0.0, model_in_force_s = 0.0;
  std::uint64_t model_evaluated = 0;
  double rmse_nm[2] = {}, bias_nm[2] = {}, noise_nm[2] = {}, systematic_nm[2] = {};
  bool at_noise_level[2] = {};
  ModelHealth model_health = ModelHealth::unknown;   ///< the badge (model_health.h)
  std::optional<std::string> previous_model_name;
  double previous_rmse_nm[2] = {};
  std::string worst_region, last_refusal, last_model_refusal;
  std::uint64_t taken = 0, evaluated = 0, refused_not_finite = 0, refused_by_model = 0,
                refused_out_of_order = 0, lost = 0, runs = 0, unit_slip_batches = 0;
  double sample_rate_hz = 0.0;
  std::string learning_state, learning, unit_error;   ///< live/learning_status.h
  std::uint64_t learning_samples_missing = 0;
  double proposal_rmse_nm[2] = {};   ///< the standing proposal's model over the window
  std::uint64_t proposal_samples = 0;
};

/// The view of a board's record (CellBoard::snapshot); members the record lacks stay 0 / "".
HealthView health_view(const ::gearcoupling::v1::TestCellRecord& record);

}  // namespace gc::status
