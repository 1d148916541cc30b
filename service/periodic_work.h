// The service's work on a clock (its status every status_interval_s, its stats line every
// stats_log_interval_s), on a thread of its own below the request path's priority.
//
// It used to run in the dispatch loop (Service::run), a thread that inherits the process's
// priority. Under the real-time deployment option that made 0.3-1.2 ms of SCHED_FIFO work once a
// second (the status's statistics sorted, its catalogue serialised and written), and a request
// or a reply woken on the same core waited behind it (docs/architecture.md, "Where a control
// loop's tail comes from"). Here the thread takes the lowest real-time priority first
// (enter_background_priority, which says why not a normal one), so the request path preempts it;
// without a real-time policy it runs as every other thread does.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace gc::service {

class PeriodicWork {
 public:
  using Clock = std::chrono::steady_clock;
  struct Task {
    Clock::duration interval;    ///< > 0; the first run is one interval after the start
    std::function<void()> run;  ///< must not throw
  };

  /// Starts the thread. Tasks due at the same time run in the order given.
  explicit PeriodicWork(std::vector<Task> tasks);
  /// stop().
  ~PeriodicWork();
  PeriodicWork(const PeriodicWork&) = delete;
  PeriodicWork& operator=(const PeriodicWork&) = delete;

  /// Returns once the thread has ended: a task running then finishes, no other starts. Safe to
  /// call more than once, from one thread at a time.
  void stop();

 private:
  void loop();

  std::vector<Task> tasks_;
  std::mutex mutex_;  ///< for the wait on stop_requested_ only: no task runs under it
  std::condition_variable stop_requested_changed_;
  std::atomic<bool> stop_requested_{false};
  std::thread thread_;  ///< last: started once the members above exist
};

}  // namespace gc::service
