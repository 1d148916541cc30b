// A ParallelFor (diagnosis/parallel_for.h) on plain threads, for the edges that run the
// diagnosis: the CLI, the benchmark and the tests. The core stays free of threads.
#pragma once

#include "diagnosis/parallel_for.h"

namespace gc {

/// Splits each call's range into `threads` contiguous chunks, runs them on threads - 1 new
/// threads and the caller, and returns when all are done; exceptions from a chunk are rethrown.
/// threads = 0 means std::thread::hardware_concurrency().
ParallelFor thread_parallel_for(unsigned threads = 0);

/// The same contract, the range handed out in small chunks (about 16 a thread) from a shared
/// counter: where a thread may be slowed more than the others (a host shared with other work),
/// the others take its share instead of waiting for it. `body` may not assume which thread or
/// how many calls cover the range.
ParallelFor chunked_parallel_for(unsigned threads = 0);

}  // namespace gc
