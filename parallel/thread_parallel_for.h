// A ParallelFor (diagnosis/parallel_for.h) on plain threads, for the edges that run the
// diagnosis: the CLI, the benchmark and the tests. The core stays free of threads.
#pragma once

#include "diagnosis/parallel_for.h"

namespace gc {

/// Splits each call's range into up to 8 contiguous chunks per thread, which `threads` - 1 new
/// threads and the caller take as each comes free, and returns when all are done; exceptions from
/// a chunk are rethrown.
/// threads = 0 means std::thread::hardware_concurrency().
ParallelFor thread_parallel_for(unsigned threads = 0);

/// `threads`, or std::thread::hardware_concurrency() (at least 1) for 0.
unsigned resolved_threads(unsigned threads);

}  // namespace gc
