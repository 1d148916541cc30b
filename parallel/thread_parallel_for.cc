#include "parallel/thread_parallel_for.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace gc {

ParallelFor thread_parallel_for(unsigned threads) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  return [threads](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
    const std::size_t chunks = std::min<std::size_t>(threads, count);
    if (chunks <= 1) {
      if (count > 0) body(0, count);
      return;
    }
    std::vector<std::exception_ptr> errors(chunks);
    const auto run = [&](std::size_t c) {
      try {
        body(c * count / chunks, (c + 1) * count / chunks);
      } catch (...) {
        errors[c] = std::current_exception();
      }
    };
    {
      std::vector<std::jthread> workers;
      for (std::size_t c = 1; c < chunks; ++c) workers.emplace_back(run, c);
      run(0);
    }
    for (const std::exception_ptr& e : errors) if (e) std::rethrow_exception(e);
  };
}

}  // namespace gc
