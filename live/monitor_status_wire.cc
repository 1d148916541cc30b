#include "live/monitor_status_wire.h"

#include <cstdio>
#include <vector>

#include "gearcoupling.h"
#include "live/health_wire.h"
#include "live/wire_text.h"
#include "protocol/dds_entity.h"

namespace gc::live {
namespace {

gearcoupling_SwapRecord swap_wire(const SwapEntry& e) {
  return {lend(e.test_cell), unix_seconds(e.at), lend(e.by), lend(e.source), e.proposal_id,
          lend(e.model_before), lend(e.model_after), e.before_rmse_nm[0], e.before_rmse_nm[1],
          e.after_rmse_nm[0], e.after_rmse_nm[1], e.after_samples, lend(e.operator_identity),
          const_cast<char*>(after_state_text(e))};
}

}  // namespace

void write_monitor_status(dds_entity_t writer, std::uint64_t monitor_id,
                          const MonitorCounters& c, const SwapAudit& audit) {
  std::vector<gearcoupling_RefusalCount> refusals;
  for (std::size_t k = 0; k < kRefusalKinds; ++k) {
    gearcoupling_RefusalCount count{};
    std::snprintf(count.kind, sizeof count.kind, "%s", refusal_kind(static_cast<Refusal>(k)));
    count.count = c.refusals[k];
    refusals.push_back(count);
  }
  std::vector<gearcoupling_SwapRecord> swaps;
  for (const SwapEntry& e : audit.entries()) swaps.push_back(swap_wire(e));
  gearcoupling_MonitorStatus out{};
  out.monitor_id = monitor_id;
  out.cells = c.cells;
  out.max_cells = c.max_cells;
  out.refused_cell_batches = c.refused_cell_batches;
  out.refused_cell_samples = c.refused_cell_samples;
  out.refused_foreign = c.refused_foreign;
  out.proposals_published = c.proposals_published;
  out.proposals_withdrawn = c.proposals_withdrawn;
  out.diagnoses_run = c.diagnoses_run;
  out.diagnoses_dropped = c.diagnoses_dropped;
  out.diagnosing = const_cast<char*>(c.diagnosing.c_str());
  out.swaps = audit.total();
  out.recent_swaps._buffer = swaps.data();
  out.recent_swaps._length = out.recent_swaps._maximum = static_cast<std::uint32_t>(swaps.size());
  out.recent_swaps._release = false;
  out.refusals._buffer = refusals.data();
  out.refusals._length = out.refusals._maximum = static_cast<std::uint32_t>(refusals.size());
  out.refusals._release = false;
  protocol::check_dds(dds_write(writer, &out), "dds_write(monitor status)");
}

void dispose_monitor_status(dds_entity_t writer, std::uint64_t monitor_id) {
  gearcoupling_MonitorStatus key{};
  key.monitor_id = monitor_id;
  dds_dispose(writer, &key);
  dds_unregister_instance(writer, &key);
}

}  // namespace gc::live
