// The monitor's own status as the MonitorStatus sample it writes (idl/gearcoupling.idl): its
// refusals, proposals and diagnoses counted, and the audit trail of swaps.
#pragma once

#include <dds/dds.h>

#include <array>
#include <cstdint>
#include <string>

#include "live/refusal_log.h"
#include "live/swap_audit.h"

namespace gc::live {

struct MonitorCounters {
  std::uint64_t cells = 0, max_cells = 0;
  std::uint64_t refused_cell_batches = 0, refused_cell_samples = 0, refused_foreign = 0;
  std::uint64_t proposals_published = 0, proposals_withdrawn = 0;
  std::uint64_t diagnoses_run = 0, diagnoses_dropped = 0;
  std::string diagnosing;   ///< the test cell being diagnosed now, "" when none
  std::array<std::uint64_t, kRefusalKinds> refusals{};   ///< by Refusal
};

void write_monitor_status(dds_entity_t writer, std::uint64_t monitor_id,
                          const MonitorCounters& counters, const SwapAudit& audit);

/// Disposes the monitor's status (a graceful stop) and unregisters it.
void dispose_monitor_status(dds_entity_t writer, std::uint64_t monitor_id);

}  // namespace gc::live
