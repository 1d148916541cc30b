// The diagnosis worker's thread priority (live/background_priority.h): nice 19, the default, is
// SCHED_IDLE; other nice values stay under the normal policy at that nice; the process's other
// threads keep theirs; a thread under SCHED_FIFO drops it (where this host lets a test raise it).
#include "live/background_priority.h"

#include <gtest/gtest.h>

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <thread>

namespace gc::live {
namespace {

struct Seen {
  int policy = -1;
  int nice = -100;
};

Seen seen_by_this_thread() {
  Seen s;
  s.policy = sched_getscheduler(0);
  errno = 0;
  s.nice = getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
  return s;
}

Seen lowered_in_a_thread(int nice, bool start_fifo = false, bool* was_fifo = nullptr) {
  Seen s;
  std::thread([&] {
    if (start_fifo) {
      sched_param p{};
      p.sched_priority = 10;
      *was_fifo = pthread_setschedparam(pthread_self(), SCHED_FIFO, &p) == 0;
    }
    lower_this_thread(nice);
    s = seen_by_this_thread();
  }).join();
  return s;
}

TEST(BackgroundPriority, NiceNineteenIsSchedIdle) {
  EXPECT_EQ(lowered_in_a_thread(19).policy, SCHED_IDLE);
}

TEST(BackgroundPriority, OtherNiceValuesStayNormalAtThatNice) {
  const Seen s = lowered_in_a_thread(7);
  EXPECT_EQ(s.policy, SCHED_OTHER);
  EXPECT_EQ(s.nice, 7);
}

TEST(BackgroundPriority, TheProcessesOtherThreadsKeepTheirPriority) {
  const Seen before = seen_by_this_thread();
  lowered_in_a_thread(19);
  const Seen after = seen_by_this_thread();
  EXPECT_EQ(after.policy, before.policy);
  EXPECT_EQ(after.nice, before.nice);
}

TEST(BackgroundPriority, ARealTimeThreadDropsItsPolicy) {
  bool was_fifo = false;
  const Seen s = lowered_in_a_thread(5, true, &was_fifo);
  if (!was_fifo) GTEST_SKIP() << "this host does not let the test run a thread under SCHED_FIFO";
  EXPECT_EQ(s.policy, SCHED_OTHER);
  EXPECT_EQ(s.nice, 5);
}

}  // namespace
}  // namespace gc::live
