// `gearcoupling status`: the domain's service instances and test cells, once or every interval,
// as tables or as JSON (one LiveStatus a line, idl/live_status.proto). The terminal view of what
// the dashboard shows; the CLI only maps its flags onto StatusReportOptions.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>

namespace gc::status {

struct StatusReportOptions {
  int domain = 0;  ///< DDS domain id [0, protocol::kMaxDomainId]
  bool json = false;
  bool watch = false;
  /// Time to discover the domain before the first report: TRANSIENT_LOCAL brings every live
  /// instance's status as soon as its writer is matched.
  std::chrono::milliseconds discovery{1500};
  std::chrono::milliseconds interval{1000};  ///< between reports, with watch
  /// With watch: stop after this many reports (0: until `stop` says so).
  unsigned count = 0;
};

/// Prints the report(s) to `out`. `stop` is asked between reports in watch mode (a signal
/// handler's flag). Returns 0. Throws protocol::DdsError when the domain cannot be joined.
int print_status(const StatusReportOptions& options, std::FILE* out,
                 const std::function<bool()>& stop = [] { return false; });

}  // namespace gc::status
