// The learning loop in Prometheus text (the dashboard's /metrics): per monitor, the proposals it
// published and withdrew, the diagnoses it ran, the swaps it took, and the test cells and foreign
// samples it refused (issue 23's counts, which were only in its log).
#pragma once

#include <string>
#include <vector>

#include "idl/live_status.pb.h"

namespace gc::status {

std::string learning_metrics_text(const std::vector<gearcoupling::v1::MonitorRecord>& monitors);

}  // namespace gc::status
