// PeriodicWork (service/periodic_work.h): the service's work on a clock, on a thread of its own
// that leaves real-time scheduling.
#include "service/periodic_work.h"

#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <mutex>
#include <optional>
#include <utility>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "service/background_priority.h"
#include "tests/service/on_fifo_thread.h"

namespace gc::service {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

/// Polls `done` every millisecond for up to 10 s; false if it never held.
template <typename Done>
bool eventually(Done done) {
  const Clock::time_point give_up = Clock::now() + std::chrono::seconds(10);
  while (!done()) {
    if (Clock::now() > give_up) return false;
    std::this_thread::sleep_for(milliseconds(1));
  }
  return true;
}

TEST(PeriodicWork, RunsEachTaskNoSoonerThanItsInterval) {
  std::mutex mutex;
  std::vector<Clock::time_point> fast_runs;
  std::vector<Clock::time_point> slow_runs;
  const Clock::time_point start = Clock::now();
  const auto recorder = [&](std::vector<Clock::time_point>& runs) {
    return [&mutex, runs = &runs] {
      std::lock_guard l(mutex);
      runs->push_back(Clock::now());
    };
  };
  PeriodicWork work(
      {{milliseconds(10), recorder(fast_runs)}, {milliseconds(40), recorder(slow_runs)}});
  ASSERT_TRUE(eventually([&] { std::lock_guard l(mutex); return slow_runs.size() >= 3; }));
  work.stop();
  std::lock_guard l(mutex);
  ASSERT_GE(fast_runs.size(), 3u);
  // The first run one interval after the start, each next one interval after the last ended.
  EXPECT_GE(fast_runs.front() - start, milliseconds(10));
  EXPECT_GE(slow_runs.front() - start, milliseconds(40));
  for (std::size_t i = 1; i < fast_runs.size(); ++i) {
    EXPECT_GE(fast_runs[i] - fast_runs[i - 1], milliseconds(10)) << "run " << i;
  }
  for (std::size_t i = 1; i < slow_runs.size(); ++i) {
    EXPECT_GE(slow_runs[i] - slow_runs[i - 1], milliseconds(40)) << "run " << i;
  }
  // Both ran meanwhile, the 10 ms task more often (about four times, on an idle host).
  EXPECT_GT(fast_runs.size(), slow_runs.size());
}

TEST(PeriodicWork, NoTaskRunsOnceStopHasReturned) {
  std::atomic<int> runs{0};
  PeriodicWork work({{milliseconds(1), [&] { runs += 1; }}});
  ASSERT_TRUE(eventually([&] { return runs >= 3; }));
  work.stop();
  const int at_stop = runs;
  std::this_thread::sleep_for(milliseconds(30));
  EXPECT_EQ(runs, at_stop);
  work.stop();  // again: returns at once
  EXPECT_EQ(runs, at_stop);
}

TEST(PeriodicWork, StopDoesNotWaitForTheNextInterval) {
  std::atomic<int> runs{0};
  const Clock::time_point start = Clock::now();
  {
    PeriodicWork work({{std::chrono::hours(1), [&] { runs += 1; }}});
  }  // the destructor stops it
  EXPECT_LT(Clock::now() - start, std::chrono::seconds(5));
  EXPECT_EQ(runs, 0);
}

TEST(PeriodicWork, ASlowTaskDoesNotPileUp) {
  std::mutex mutex;
  std::vector<std::pair<Clock::time_point, Clock::time_point>> runs;  // start, end
  PeriodicWork work({{milliseconds(5), [&] {
                        const Clock::time_point begun = Clock::now();
                        std::this_thread::sleep_for(milliseconds(20));
                        std::lock_guard l(mutex);
                        runs.emplace_back(begun, Clock::now());
                      }}});
  ASSERT_TRUE(eventually([&] { std::lock_guard l(mutex); return runs.size() >= 4; }));
  work.stop();
  std::lock_guard l(mutex);
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_GE(runs[i].first - runs[i - 1].second, milliseconds(5)) << "run " << i;
  }
}

/// The calling thread's policy and priority.
std::pair<int, int> policy_and_priority() {
  int policy = -1;
  sched_param param{};
  pthread_getschedparam(pthread_self(), &policy, &param);
  return {policy, param.sched_priority};
}

TEST(BackgroundPriority, LeavesANormalThreadAsItIs) {
  std::pair<int, int> after{-1, -1};
  std::thread([&] {
    EXPECT_FALSE(enter_background_priority());
    after = policy_and_priority();
  }).join();
  EXPECT_EQ(after, std::make_pair(SCHED_OTHER, 0));
}

TEST(BackgroundPriority, TakesTheLowestPriorityOfARealTimeThreadsPolicy) {
  bool changed = false;
  std::pair<int, int> after{-1, -1};
  if (!test::on_fifo_thread(10, [&] {
        changed = enter_background_priority();
        after = policy_and_priority();
      })) {
    GTEST_SKIP() << "SCHED_FIFO refused (no CAP_SYS_NICE)";
  }
  EXPECT_TRUE(changed);
  // Still real-time (no normal process preempts it), below every other priority of the policy.
  EXPECT_EQ(after, std::make_pair(SCHED_FIFO, sched_get_priority_min(SCHED_FIFO)));
}

// The reason PeriodicWork exists: made by a real-time thread, as the service's dispatch loop is
// under the real-time deployment option, its thread must not keep that priority. A thread made
// the same way without it does: the check would fail if the priority were not lowered.
TEST(PeriodicWork, ItsThreadRunsBelowTheRealTimePriorityOfItsCreator) {
  std::pair<int, int> made_plainly{-1, -1};
  std::mutex mutex;
  std::optional<std::pair<int, int>> periodic;
  if (!test::on_fifo_thread(10, [&] {
        std::thread([&] { made_plainly = policy_and_priority(); }).join();
        PeriodicWork work({{milliseconds(1), [&] {
                              std::lock_guard l(mutex);
                              periodic = policy_and_priority();
                            }}});
        eventually([&] { std::lock_guard l(mutex); return periodic.has_value(); });
      })) {
    GTEST_SKIP() << "SCHED_FIFO refused (no CAP_SYS_NICE)";
  }
  EXPECT_EQ(made_plainly, std::make_pair(SCHED_FIFO, 10));
  ASSERT_TRUE(periodic.has_value());
  EXPECT_EQ(*periodic, std::make_pair(SCHED_FIFO, sched_get_priority_min(SCHED_FIFO)));
}

}  // namespace
}  // namespace gc::service
