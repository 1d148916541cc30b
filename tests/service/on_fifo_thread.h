// Running a piece of a test on a thread of its own under SCHED_FIFO, the test's other threads
// left as they are.
#pragma once

#include <pthread.h>
#include <sched.h>

#include <thread>

namespace gc::test {

/// Runs `body` on a new thread made SCHED_FIFO at `priority` and waits for it. False, without
/// running `body`, when the policy is refused (no CAP_SYS_NICE): the caller skips its test.
template <typename Body>
bool on_fifo_thread(int priority, Body body) {
  bool refused = false;
  std::thread([&] {
    const sched_param fifo{priority};
    if (pthread_setschedparam(pthread_self(), SCHED_FIFO, &fifo) != 0) {
      refused = true;
      return;
    }
    body();
  }).join();
  return !refused;
}

}  // namespace gc::test
