// A test cell's HealthReport as the CellHealth sample the monitor writes (idl/gearcoupling.idl).
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <string>

#include "gearcoupling.h"
#include "live/cell_monitor.h"

namespace gc::live {

/// Writes `report` through `writer` as test cell `test_cell`'s CellHealth. The strings are
/// lent, not copied: nothing outlives the call.
void write_health(dds_entity_t writer, const std::string& test_cell, std::uint64_t monitor_id,
                  bool stale, const HealthReport& report);

/// Disposes test cell `test_cell`'s CellHealth instance and unregisters it (the writer keeps
/// nothing of it).
void dispose_health(dds_entity_t writer, const std::string& test_cell);

/// The seconds since 1970 of `time` [s].
double unix_seconds(std::chrono::system_clock::time_point time);

}  // namespace gc::live
