// The terminal view of the boards (`gearcoupling status`): one row per instance and
// calculation, service times in milliseconds.
#pragma once

#include <cstdio>
#include <vector>

#include "clients/status/instance_board.h"

namespace gc::status {

/// Prints the instances as a table to `out`, or a line saying none was seen.
void print_instances(const std::vector<InstanceView>& instances, std::FILE* out);

}  // namespace gc::status
