// The faults of one user-space network link between two test hosts (tests/service/faulty_link.cc):
// when each frame that enters the link leaves it, if at all. What netem would do, for a kernel
// without CONFIG_NET_SCH_NETEM. Frames keep their order unless one is picked for reordering.
#pragma once

#include <chrono>
#include <cstdint>
#include <random>
#include <vector>

namespace gc::test {

struct LinkFaults {
  double loss = 0.0;       ///< probability that a frame is dropped, [0, 1]
  double delay_s = 0.0;    ///< one-way delay, mean [s], [0, 10]
  double jitter_s = 0.0;   ///< the delay varies uniformly within +- this [s], [0, delay_s]
  double duplicate = 0.0;  ///< probability that a frame leaves twice, [0, 1]
  double reorder = 0.0;    ///< probability that a frame skips the delay and overtakes, [0, 1]
};

/// Throws std::invalid_argument naming the field, its value and the allowed range.
void check(const LinkFaults& faults);

/// What a link did to the frames it was given.
struct LinkCounts {
  std::uint64_t frames = 0;      ///< entered the link
  std::uint64_t lost = 0;        ///< dropped by `loss`
  std::uint64_t duplicated = 0;  ///< sent twice
  std::uint64_t reordered = 0;   ///< sent at once, ahead of any frames still delayed
  double delay_sum_s = 0.0;      ///< the delays of the frames not lost, added up [s]
  double delay_max_s = 0.0;      ///< the longest of them [s]
};

/// Decides, frame by frame, when its copies leave the link: none (lost), one, or two
/// (duplicated). A frame's delay is delay_s + U(-jitter_s, jitter_s), but never earlier than
/// the frame before it (a FIFO, as a real link's queue), except for a reordered frame, which
/// leaves at once. Deterministic for a seed.
class FaultSchedule {
 public:
  using Clock = std::chrono::steady_clock;

  FaultSchedule(LinkFaults faults, std::uint64_t seed);
  /// The departure times of the copies of a frame that arrives at `arrival`.
  std::vector<Clock::time_point> departures(Clock::time_point arrival);
  const LinkCounts& counts() const { return counts_; }

 private:
  bool happens(double probability) { return probability > 0.0 && uniform_(random_) < probability; }

  LinkFaults faults_;
  std::mt19937_64 random_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  Clock::time_point last_in_order_{};
  LinkCounts counts_;
};

}  // namespace gc::test
