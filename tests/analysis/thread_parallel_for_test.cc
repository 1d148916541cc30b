// thread_parallel_for (parallel/thread_parallel_for.h), the ParallelFor that diagnose runs on:
// every index once, calls nested within a chunk, an exception rethrown, and a thread that stalls
// holding back only its own chunk while the other threads take the rest.
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "parallel/thread_parallel_for.h"

namespace gc {
namespace {

TEST(ThreadParallelFor, CoversEveryIndexOnceNestedCallsToo) {
  const ParallelFor parallel_for = thread_parallel_for(3);
  for (const std::size_t count : {0u, 1u, 2u, 5u, 47u, 1000u, 100000u}) {
    std::vector<std::atomic<int>> hits(count);
    parallel_for(count, [&](std::size_t begin, std::size_t end) {
      ASSERT_LT(begin, end);
      ASSERT_LE(end, count);
      for (std::size_t i = begin; i < end; ++i) ++hits[i];
    });
    for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(hits[i], 1) << count << " " << i;
  }
  // The diagnosis fits candidates side by side, each predicting its rows in parallel.
  std::vector<std::atomic<int>> hits(6 * 500);
  parallel_for(6, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c) {
      parallel_for(500, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) ++hits[c * 500 + i];
      });
    }
  });
  for (const auto& h : hits) ASSERT_EQ(h, 1);
}

TEST(ThreadParallelFor, RethrowsAChunksException) {
  const ParallelFor parallel_for = thread_parallel_for(2);
  EXPECT_THROW(parallel_for(10000, [](std::size_t begin, std::size_t end) {
                 if (begin <= 5000 && 5000 < end) throw std::runtime_error("chunk");
               }),
               std::runtime_error);
}

// The chunk holding index 0 does not return until the others have covered 80 % of the range (or
// 10 s have passed). Cut in one contiguous half a thread, the other thread could cover only 50 %.
TEST(ThreadParallelFor, AStalledThreadHoldsBackOnlyItsOwnChunk) {
  const ParallelFor parallel_for = thread_parallel_for(2);
  constexpr std::size_t kCount = 10000;
  std::atomic<std::size_t> elsewhere{0};
  bool waited_out = false;
  parallel_for(kCount, [&](std::size_t begin, std::size_t end) {
    if (begin == 0) {
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (elsewhere < kCount * 8 / 10 && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      waited_out = elsewhere < kCount * 8 / 10;
      return;
    }
    elsewhere += end - begin;
  });
  EXPECT_FALSE(waited_out) << "the other thread covered only " << elsewhere << " of " << kCount;
}

}  // namespace
}  // namespace gc
