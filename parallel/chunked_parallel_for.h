// A ParallelFor (diagnosis/parallel_for.h) for a host shared with other work, where a thread
// may not run for milliseconds: the range is handed out in small chunks from a shared counter,
// so the threads that run take the share of one that does not, and a call waits only for the
// chunks begun, never for a thread that has not started (validate: joining threads started
// per call took a third of its time at load 3 on 2 cores).
#pragma once

#include "diagnosis/parallel_for.h"

namespace gc {

/// Runs each call's range in chunks (about 16 a thread) on the caller and on threads - 1
/// threads that live as long as the returned ParallelFor and its copies; returns when every
/// chunk is done; rethrows the first exception from a chunk (the chunks not begun are skipped).
/// Calls must not overlap or nest: one caller at a time. `body` may not assume which thread
/// or how many calls cover the range. threads = 0 means std::thread::hardware_concurrency().
ParallelFor chunked_parallel_for(unsigned threads = 0);

}  // namespace gc
