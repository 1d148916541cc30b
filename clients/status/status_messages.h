// The boards' views as the messages of idl/live_status.proto, which the dashboard sends the
// browser and `gearcoupling status --json` prints (codec::to_json, protobuf's JSON mapping).
#pragma once

#include <vector>

#include "clients/status/instance_board.h"
#include "idl/live_status.pb.h"

namespace gc::status {

namespace v1 = ::gearcoupling::v1;

v1::ServiceInstanceRecord to_message(const InstanceView& instance);

/// Every instance and test cell (from CellBoard), stamped with the wall-clock time now.
v1::LiveStatus to_message(const std::vector<InstanceView>& instances,
                          const std::vector<v1::TestCellRecord>& cells);

/// Adds the monitors' status (refusals, audit trail) and the proposals (MonitorBoard) to `status`.
void add_learning(const std::vector<v1::MonitorRecord>& monitors,
                  const std::vector<v1::ProposalRecord>& proposals, v1::LiveStatus& status);

}  // namespace gc::status
