#include "parallel/chunked_parallel_for.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "parallel/thread_parallel_for.h"

namespace gc {
namespace {

using Body = std::function<void(std::size_t, std::size_t)>;

// One call's range; its chunks are claimed from `next` by whoever joined it.
struct Job {
  std::size_t count = 0;
  std::size_t chunk = 1;
  const Body* body = nullptr;
  std::atomic<std::size_t> next{0};
  std::mutex error_mutex;
  std::exception_ptr error;

  void run_chunks() {
    for (std::size_t begin = next.fetch_add(chunk); begin < count; begin = next.fetch_add(chunk)) {
      try {
        (*body)(begin, std::min(count, begin + chunk));
      } catch (...) {
        next = count;  // no further chunks
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  }
};

// Threads waiting for a job. A thread joins the open job under the mutex; the caller closes it
// when its own claims run dry and waits only for the threads that joined.
class Pool {
 public:
  explicit Pool(unsigned threads) {
    for (unsigned t = 1; t < threads; ++t) workers_.emplace_back([this] { work(); });
  }
  ~Pool() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
  }
  Pool(const Pool&) = delete;
  Pool& operator=(const Pool&) = delete;

  std::size_t threads() const { return workers_.size() + 1; }

  void run(Job& job) {
    {
      const std::lock_guard lock(mutex_);
      job_ = &job;
      ++generation_;
    }
    wake_.notify_all();
    job.run_chunks();
    std::unique_lock lock(mutex_);
    job_ = nullptr;
    done_.wait(lock, [this] { return joined_ == 0; });
  }

 private:
  void work() {
    std::unique_lock lock(mutex_);
    std::size_t seen = 0;
    for (;;) {
      wake_.wait(lock, [&] { return stopping_ || (job_ != nullptr && generation_ != seen); });
      if (stopping_) return;
      seen = generation_;
      Job& job = *job_;
      ++joined_;
      lock.unlock();
      job.run_chunks();
      lock.lock();
      if (--joined_ == 0) done_.notify_all();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  Job* job_ = nullptr;           // the open job, null when closed
  std::size_t generation_ = 0;   // jobs opened so far: a thread joins each at most once
  std::size_t joined_ = 0;       // threads in the current job
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace

ParallelFor chunked_parallel_for(unsigned threads) {
  auto pool = std::make_shared<Pool>(resolved_threads(threads));
  return [pool](std::size_t count, const Body& body) {
    const std::size_t threads = std::min<std::size_t>(pool->threads(), count);
    if (threads <= 1) {
      if (count > 0) body(0, count);
      return;
    }
    Job job;
    job.count = count;
    job.chunk = std::max<std::size_t>(1, count / (16 * threads));
    job.body = &body;
    pool->run(job);
    if (job.error) std::rethrow_exception(job.error);
  };
}

}  // namespace gc
