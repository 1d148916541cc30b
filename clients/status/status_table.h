// The terminal view of the boards (`gearcoupling status`): one row per instance and
// calculation, service times in milliseconds.
#pragma once

#include <cstdio>
#include <vector>

#include "clients/status/instance_board.h"
#include "idl/live_status.pb.h"

namespace gc::status {

/// Prints the instances as a table to `out`, or a line saying none was seen.
void print_instances(const std::vector<InstanceView>& instances, std::FILE* out);

/// Prints the test cells (from CellBoard): state, model in force, samples, RMSE against the
/// noise per channel and the worst region; nothing when there is none.
void print_cells(const std::vector<gearcoupling::v1::TestCellRecord>& cells, std::FILE* out);

}  // namespace gc::status
