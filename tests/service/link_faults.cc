#include "tests/service/link_faults.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace gc::test {
namespace {

void check_range(const char* field, double value, double low, double high) {
  if (std::isfinite(value) && value >= low && value <= high) return;
  std::ostringstream message;
  message << "link fault " << field << " = " << value << " is outside [" << low << ", " << high << "]";
  throw std::invalid_argument(message.str());
}

}  // namespace

void check(const LinkFaults& faults) {
  check_range("loss", faults.loss, 0.0, 1.0);
  check_range("delay_s", faults.delay_s, 0.0, 10.0);
  check_range("jitter_s", faults.jitter_s, 0.0, std::isfinite(faults.delay_s) ? faults.delay_s : 0.0);
  check_range("duplicate", faults.duplicate, 0.0, 1.0);
  check_range("reorder", faults.reorder, 0.0, 1.0);
}

FaultSchedule::FaultSchedule(LinkFaults faults, std::uint64_t seed) : faults_(faults), random_(seed) {
  check(faults_);
}

std::vector<FaultSchedule::Clock::time_point> FaultSchedule::departures(Clock::time_point arrival) {
  counts_.frames += 1;
  if (happens(faults_.loss)) {
    counts_.lost += 1;
    return {};
  }
  Clock::time_point leaves = arrival;
  if (happens(faults_.reorder)) {
    counts_.reordered += 1;
  } else {
    const double drawn_s = faults_.delay_s + faults_.jitter_s * (2.0 * uniform_(random_) - 1.0);
    leaves = std::max(arrival + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(drawn_s)),
                      last_in_order_);
    last_in_order_ = leaves;
  }
  const double delay_s = std::chrono::duration<double>(leaves - arrival).count();
  counts_.delay_sum_s += delay_s;
  counts_.delay_max_s = std::max(counts_.delay_max_s, delay_s);
  if (!happens(faults_.duplicate)) return {leaves};
  counts_.duplicated += 1;
  return {leaves, leaves};
}

}  // namespace gc::test
