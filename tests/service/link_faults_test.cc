// The faulty link's schedule (link_faults.h): its faults happen at the rates asked, delays stay
// within delay +- jitter, order is kept except for reordered frames, and bad settings are
// refused with the field, the value and the range.
#include "tests/service/link_faults.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace gc::test {
namespace {

using Clock = FaultSchedule::Clock;
using std::chrono::microseconds;

constexpr int kFrames = 100000;

TEST(LinkFaults, LossDuplicationAndReorderingHappenAtTheRatesAsked) {
  FaultSchedule schedule({0.10, 0.020, 0.010, 0.01, 0.01}, 7);
  Clock::time_point t{};
  std::size_t copies = 0;
  for (int i = 0; i < kFrames; ++i) copies += schedule.departures(t += microseconds(1000)).size();
  const LinkCounts& c = schedule.counts();
  EXPECT_EQ(c.frames, static_cast<std::uint64_t>(kFrames));
  // Binomial: 4 standard deviations either side.
  EXPECT_NEAR(static_cast<double>(c.lost) / kFrames, 0.10, 4 * std::sqrt(0.1 * 0.9 / kFrames));
  EXPECT_NEAR(static_cast<double>(c.duplicated) / (kFrames - c.lost), 0.01, 4 * std::sqrt(0.01 * 0.99 / kFrames) * 1.1);
  EXPECT_NEAR(static_cast<double>(c.reordered) / (kFrames - c.lost), 0.01, 4 * std::sqrt(0.01 * 0.99 / kFrames) * 1.1);
  EXPECT_EQ(copies, kFrames - c.lost + c.duplicated);
}

TEST(LinkFaults, SparseFramesAreDelayedWithinDelayPlusMinusJitterAndKeepTheirOrder) {
  FaultSchedule schedule({0.0, 0.020, 0.010, 0.0, 0.0}, 11);
  Clock::time_point t{};
  Clock::time_point previous{};
  double sum_s = 0.0;
  for (int i = 0; i < 10000; ++i) {
    t += microseconds(25000);  // farther apart than the largest delay difference
    const auto leaves = schedule.departures(t);
    ASSERT_EQ(leaves.size(), 1u);
    const double delay_s = std::chrono::duration<double>(leaves[0] - t).count();
    EXPECT_GE(delay_s, 0.010 - 1e-9);
    EXPECT_LE(delay_s, 0.030 + 1e-9);
    EXPECT_GT(leaves[0], previous);
    previous = leaves[0];
    sum_s += delay_s;
  }
  EXPECT_NEAR(sum_s / 10000, 0.020, 0.0005);
  EXPECT_NEAR(schedule.counts().delay_max_s, 0.030, 0.0005);
}

TEST(LinkFaults, CloseFramesNeverOvertakeEachOtherUnlessReordered) {
  FaultSchedule in_order({0.0, 0.020, 0.010, 0.0, 0.0}, 3);
  FaultSchedule reordering({0.0, 0.020, 0.010, 0.0, 0.5}, 3);
  Clock::time_point t{};
  Clock::time_point last_in_order{}, last_reordering{};
  int overtaken = 0;
  for (int i = 0; i < 1000; ++i) {
    t += microseconds(100);
    const Clock::time_point a = in_order.departures(t).at(0);
    EXPECT_GE(a, last_in_order);
    last_in_order = a;
    const Clock::time_point b = reordering.departures(t).at(0);
    overtaken += b < last_reordering;
    last_reordering = std::max(last_reordering, b);
  }
  EXPECT_GT(overtaken, 100) << "half the frames skip the delay, most of them ahead of frames still delayed";
}

TEST(LinkFaults, ALinkWithoutFaultsPassesEveryFrameAtOnce) {
  FaultSchedule schedule({}, 1);
  const Clock::time_point t = Clock::now();
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(schedule.departures(t), std::vector<Clock::time_point>{t});
}

TEST(LinkFaults, BadSettingsAreRefusedNamingTheFieldTheValueAndTheRange) {
  const auto message = [](const LinkFaults& faults) {
    try {
      check(faults);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message({1.5, 0, 0, 0, 0}), "link fault loss = 1.5 is outside [0, 1]");
  EXPECT_EQ(message({0, -0.001, 0, 0, 0}), "link fault delay_s = -0.001 is outside [0, 10]");
  EXPECT_EQ(message({0, 0.01, 0.02, 0, 0}), "link fault jitter_s = 0.02 is outside [0, 0.01]");
  EXPECT_EQ(message({0, 0, 0, std::nan(""), 0}), "link fault duplicate = nan is outside [0, 1]");
  EXPECT_EQ(message({0, 0, 0, 0, -1}), "link fault reorder = -1 is outside [0, 1]");
  EXPECT_EQ(message({0.1, 0.02, 0.01, 0.01, 0.01}), "accepted");
  EXPECT_THROW(FaultSchedule({2.0, 0, 0, 0, 0}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace gc::test
