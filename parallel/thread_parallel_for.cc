#include "parallel/thread_parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace gc {

namespace {

/// Chunks per thread of a range: enough to even out uneven chunks, few enough that a chunk's own
/// setup (a model's copy with its history) stays small beside its rows.
constexpr std::size_t kChunksPerThread = 8;

// Runs run(0) .. run(workers - 1), run(0) on the caller; rethrows the first exception.
void on_threads(std::size_t workers, const std::function<void(std::size_t)>& run) {
  std::vector<std::exception_ptr> errors(workers);
  {
    std::vector<std::jthread> threads;
    for (std::size_t w = 1; w < workers; ++w) {
      threads.emplace_back([&, w] {
        try {
          run(w);
        } catch (...) {
          errors[w] = std::current_exception();
        }
      });
    }
    try {
      run(0);
    } catch (...) {
      errors[0] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : errors) if (e) std::rethrow_exception(e);
}

}  // namespace

unsigned resolved_threads(unsigned threads) {
  return threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : threads;
}

ParallelFor thread_parallel_for(unsigned threads) {
  threads = resolved_threads(threads);
  return [threads](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
    const std::size_t workers = std::min<std::size_t>(threads, count);
    if (workers <= 1) {
      if (count > 0) body(0, count);
      return;
    }
    // More chunks than threads, each taken by whichever thread is free: the halves of a range
    // rarely cost the same (the candidates' fits, a few rows' refusals), and on a host whose
    // cores are busy with others, one thread runs slower than the other.
    const std::size_t chunks = std::min<std::size_t>(count, kChunksPerThread * workers);
    std::atomic<std::size_t> next{0};
    on_threads(workers, [&](std::size_t) {
      for (std::size_t c = next++; c < chunks; c = next++) body(c * count / chunks, (c + 1) * count / chunks);
    });
  };
}

}  // namespace gc
