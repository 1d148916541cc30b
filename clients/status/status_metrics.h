// /metrics of the dashboard: the boards' views in Prometheus text (docs/dashboard.md lists every
// metric). Counters are the services' own since they started: Prometheus's rate() handles their
// restarts.
#pragma once

#include <string>
#include <vector>

#include "clients/status/instance_board.h"
#include "idl/live_status.pb.h"

namespace gc::status {

namespace v1 = ::gearcoupling::v1;

/// Families for every instance: up, accepting, uptime, requests served and failed, service
/// time quantiles, labelled by instance (16 hex digits), host and calculation.
/// Then per test cell: up, samples taken, evaluated, refused (by reason) and lost, and per
/// channel (M_sy', M_sz') the rolling RMSE and the noise level, labelled by test_cell.
std::string metrics_text(const std::vector<InstanceView>& instances,
                         const std::vector<v1::TestCellRecord>& cells);

}  // namespace gc::status
