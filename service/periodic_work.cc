#include "service/periodic_work.h"

#include <pthread.h>

#include <algorithm>
#include <utility>

#include "service/background_priority.h"

namespace gc::service {

PeriodicWork::PeriodicWork(std::vector<Task> tasks)
    : tasks_(std::move(tasks)), thread_([this] { loop(); }) {}

PeriodicWork::~PeriodicWork() { stop(); }

void PeriodicWork::stop() {
  {
    std::lock_guard lock(mutex_);  // not between the loop's test of the flag and its wait
    stop_requested_ = true;
  }
  stop_requested_changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void PeriodicWork::loop() {
  pthread_setname_np(pthread_self(), "periodic");  // as `top -H` and /proc show it
  enter_background_priority();
  std::vector<Clock::time_point> due(tasks_.size());
  const Clock::time_point start = Clock::now();
  for (std::size_t i = 0; i < tasks_.size(); ++i) due[i] = start + tasks_[i].interval;
  const auto stopping = [this] { return stop_requested_.load(); };
  while (!stopping()) {
    {
      std::unique_lock lock(mutex_);
      if (due.empty()) {
        stop_requested_changed_.wait(lock, stopping);
      } else {
        stop_requested_changed_.wait_until(lock, *std::min_element(due.begin(), due.end()),
                                           stopping);
      }
    }
    const Clock::time_point now = Clock::now();
    for (std::size_t i = 0; i < tasks_.size() && !stopping(); ++i) {
      if (now < due[i]) continue;
      tasks_[i].run();
      due[i] = Clock::now() + tasks_[i].interval;  // after the run: a slow run never piles up
    }
  }
}

}  // namespace gc::service
