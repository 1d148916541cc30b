// Requests served and failed per calculation and the service time distribution, for the status
// topic and the periodic log line. Thread-safe.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <vector>

#include "gearcoupling.h"
#include "protocol/calculation.h"

namespace gc::service {

/// How a request was answered, as the status counts it.
enum class ReplyOutcome {
  served,   ///< STATUS_OK
  refused,  ///< the client's input: STATUS_INVALID_INPUT, STATUS_UNKNOWN_COUPLING
  failed,   ///< the service's or the model's failure: any other status
};

/// The outcome of a reply with wire status `status`.
ReplyOutcome reply_outcome(gearcoupling_ReplyStatus status);

struct CalculationSnapshot {
  std::uint64_t served = 0;      ///< ReplyOutcome::served
  std::uint64_t failed = 0;      ///< ReplyOutcome::failed
  std::uint64_t refused = 0;     ///< ReplyOutcome::refused
  double p50_service_time_s = 0.0;  ///< over the last kWindow requests [s]
  double p99_service_time_s = 0.0;
  double service_time_sum_s = 0.0;  ///< over every request since start [s]
};

class ServiceStats {
 public:
  static constexpr std::size_t kWindow = 4096;

  /// One answered request: how, and its service time (taken from the reader to reply
  /// written) [s].
  void record(protocol::Calculation calculation, ReplyOutcome outcome, double service_time_s);
  std::array<CalculationSnapshot, gc::protocol::kCalculationCount> snapshot() const;
  /// A request refused for a forged client_id (not answered, not in served or failed).
  void record_forged() { forged_ += 1; }
  std::uint64_t forged() const { return forged_; }
  /// A request about to be answered in the request listener (inline_answer.h), not on a worker.
  void record_answered_inline() { answered_inline_ += 1; }
  std::uint64_t answered_inline() const { return answered_inline_; }

 private:
  struct PerCalculation {
    std::uint64_t served = 0;
    std::uint64_t failed = 0;
    std::uint64_t refused = 0;
    double service_time_sum_s = 0.0;
    std::vector<double> window;  ///< ring buffer of the last kWindow service times
    std::size_t next = 0;
  };
  mutable std::mutex mutex_;
  std::array<PerCalculation, gc::protocol::kCalculationCount> calculations_;
  std::atomic<std::uint64_t> forged_{0};
  std::atomic<std::uint64_t> answered_inline_{0};
};

}  // namespace gc::service
