// A client's fixed-rate run of checked requests on a test host (tests/service/client_on_host.h),
// for the network-fault tests: induced-moment requests at a fixed rate, each answer compared bit
// for bit with the core's own result, each outcome counted once per request (a second call of a
// request's callback is a duplicate; no call at all by the end, a silent loss), latencies kept.
// The test marks when it cuts and heals a link by signals (SIGUSR2: partition, SIGUSR1: heal),
// so that the run can say how long the service took to answer again.
#pragma once

#include <chrono>
#include <cstddef>
#include <map>
#include <string>

#include "tests/service/client_on_host.h"

namespace gc::test {

struct RunPlan {
  int domain = 0;
  std::size_t instances = 1;  ///< service instances to find before the first request
  double rate_hz = 200.0;     ///< requests per second; a slot missed (a call waiting for an instance) is skipped
  double duration_s = 10.0;   ///< from the first request to the last
  std::chrono::milliseconds timeout{5000};  ///< each call's
};

/// Runs `plan` in a ClientOnHost child. Says "running" when the instances are found, just
/// before the first request. Returns "report" and key=value figures: requests, answered,
/// timeouts, errors (other failures), wrong (an answer not the core's), repeated (a request
/// whose callback ran more than once), silent (no outcome at all), p50_ms, p99_ms, max_ms (of
/// the answered), recovery_s (heal to the first answer after it; -1 without a heal or an
/// answer), rejoin_s (heal to all `instances` known again; -1 if never), least_served_after_heal
/// (of the instances known at the end, the fewest answers one served since the heal), and the
/// client's counters sent, replies, resent, dropped_duplicates, client_timeouts.
std::string fixed_rate_run(const RunPlan& plan, const ClientOnHost::Say& say);

/// A report's figures by key; throws std::runtime_error if `line` is not a report.
std::map<std::string, double> parse_report(const std::string& line);

}  // namespace gc::test
