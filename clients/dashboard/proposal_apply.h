// The dashboard's "apply" button (POST /api/apply): puts a monitor's standing proposal in force
// for a test cell, as `gearcoupling swap-model --proposal ID` does (live/model_swap_publisher.h).
// Only a dashboard started with --operator-cells may: it then writes model swaps for those test
// cells, which under DDS Security needs an operator identity granted them (docs/security.md).
// Any other dashboard stays read-only and answers 403.
#pragma once

#include <dds/dds.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "clients/dashboard/query_panel.h"
#include "clients/status/monitor_board.h"
#include "live/model_swap_publisher.h"

namespace gc::dashboard {

class ProposalApplier {
 public:
  /// `operator_cells` empty: read-only. Otherwise one model writer per cell on `participant`
  /// (throws std::runtime_error naming --operator-cells and why when the identity may not, e.g.
  /// a dashboard-* identity), whose swaps the audit trail says are by `operator_name` (the
  /// person, --operator), or by the operator identity operator-NAME when it is empty
  /// (live::swap_operator; throws InvalidInput naming "--operator" when neither names anyone).
  ProposalApplier(dds_entity_t participant, status::MonitorBoard& proposals,
                  std::vector<std::string> operator_cells, const std::string& operator_name = "");

  /// Parameters test_cell and proposal (16 hex digits). 200 {"applied": ID, "model": NAME};
  /// 403 when this dashboard may not apply (read-only, or not that test cell); 400 naming a
  /// missing parameter; 404 when the test cell has no such proposal; 409 when it is not standing.
  JsonAnswer apply(const std::map<std::string, std::string>& parameters) const;

  const std::vector<std::string>& operator_cells() const { return cells_; }

 private:
  status::MonitorBoard& proposals_;
  std::vector<std::string> cells_;
  std::string by_;   ///< who applies, for the log (the audit trail has it from USER_DATA)
  std::unique_ptr<live::ModelSwapPublisher> swaps_;
};

}  // namespace gc::dashboard
