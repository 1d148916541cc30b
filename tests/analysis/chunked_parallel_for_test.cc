// chunked_parallel_for (parallel/chunked_parallel_for.h), the ParallelFor that validate reads
// and predicts on: every index once per call, call after call on the same threads, an
// exception from a chunk rethrown to the caller, and ranges shorter than the thread count.
#include <atomic>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "parallel/chunked_parallel_for.h"

namespace gc {
namespace {

TEST(ChunkedParallelFor, CoversEveryIndexOnceCallAfterCall) {
  const ParallelFor parallel_for = chunked_parallel_for(3);
  for (const std::size_t count : {0u, 1u, 2u, 5u, 1000u, 100000u}) {
    for (int call = 0; call < 20; ++call) {
      std::vector<std::atomic<int>> hits(count);
      parallel_for(count, [&](std::size_t begin, std::size_t end) {
        ASSERT_LE(begin, end);
        ASSERT_LE(end, count);
        for (std::size_t i = begin; i < end; ++i) ++hits[i];
      });
      for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(hits[i], 1) << count << " " << i;
    }
  }
}

TEST(ChunkedParallelFor, RethrowsAChunksExceptionAndRunsOn) {
  const ParallelFor parallel_for = chunked_parallel_for(2);
  EXPECT_THROW(parallel_for(10000, [](std::size_t begin, std::size_t end) {
                 if (begin <= 5000 && 5000 < end) throw std::runtime_error("chunk");
               }),
               std::runtime_error);
  std::atomic<std::size_t> covered{0};
  parallel_for(10000, [&](std::size_t begin, std::size_t end) { covered += end - begin; });
  EXPECT_EQ(covered, 10000u);
}

TEST(ChunkedParallelFor, CopiesShareTheThreadsAndOutliveTheOriginal) {
  ParallelFor copy;
  {
    const ParallelFor original = chunked_parallel_for(2);
    copy = original;
  }
  std::atomic<std::size_t> covered{0};
  copy(777, [&](std::size_t begin, std::size_t end) { covered += end - begin; });
  EXPECT_EQ(covered, 777u);
}

}  // namespace
}  // namespace gc
