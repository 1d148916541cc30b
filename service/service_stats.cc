#include "service/service_stats.h"

#include <algorithm>
#include <cmath>

#include "protocol/reply_status.h"

namespace gc::service {
namespace {

/// Nearest-rank percentile of `sorted` (not empty), p in (0, 1].
double percentile(const std::vector<double>& sorted, double p) {
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
  return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

}  // namespace

ReplyOutcome reply_outcome(gearcoupling_ReplyStatus status) {
  if (status == gearcoupling_STATUS_OK) return ReplyOutcome::served;
  return protocol::refuses_input(status) ? ReplyOutcome::refused : ReplyOutcome::failed;
}

void ServiceStats::record(protocol::Calculation calculation, ReplyOutcome outcome,
                          double service_time_s) {
  std::lock_guard lock(mutex_);
  PerCalculation& c = calculations_[protocol::index_of(calculation)];
  (outcome == ReplyOutcome::served    ? c.served
   : outcome == ReplyOutcome::refused ? c.refused
                                      : c.failed) += 1;
  c.service_time_sum_s += service_time_s;
  if (c.window.size() < kWindow) {
    c.window.push_back(service_time_s);
  } else {
    c.window[c.next] = service_time_s;
  }
  c.next = (c.next + 1) % kWindow;
}

std::array<CalculationSnapshot, gc::protocol::kCalculationCount> ServiceStats::snapshot() const {
  // Copied under the lock, one calculation at a time into room made before, and sorted outside
  // it: record() runs on the round trip's own thread (the request listener), and a sort of
  // 6 x 4096 service times under this lock, made by the dispatch loop once a second for the
  // status topic, was a wait of up to a millisecond on that thread behind the dispatch loop
  // and, on a busy host, behind whatever preempted it (docs/architecture.md, "No lock of the
  // round trip held by periodic work").
  std::array<CalculationSnapshot, gc::protocol::kCalculationCount> out;
  std::vector<double> window;
  window.reserve(kWindow);
  for (std::size_t i = 0; i < calculations_.size(); ++i) {
    {
      std::lock_guard lock(mutex_);
      const PerCalculation& c = calculations_[i];
      out[i].served = c.served;
      out[i].failed = c.failed;
      out[i].refused = c.refused;
      out[i].service_time_sum_s = c.service_time_sum_s;
      window.assign(c.window.begin(), c.window.end());  // within the reserved room: no allocation
    }
    if (!window.empty()) {
      std::sort(window.begin(), window.end());
      out[i].p50_service_time_s = percentile(window, 0.50);
      out[i].p99_service_time_s = percentile(window, 0.99);
    }
  }
  return out;
}

}  // namespace gc::service
