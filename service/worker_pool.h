// A fixed pool of threads running submitted jobs in order of submission.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace gc::service {

class WorkerPool {
 public:
  /// Starts `threads` workers (at least one).
  explicit WorkerPool(std::size_t threads);
  /// drain_and_stop().
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Queues `job`. Jobs must not throw.
  void submit(std::function<void()> job);
  /// Runs every job already queued, then stops and joins the workers. Idempotent.
  void drain_and_stop();

  std::size_t threads() const { return threads_.size(); }
  /// Jobs queued and not yet started.
  std::size_t queued() const;

 private:
  void work();

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace gc::service
