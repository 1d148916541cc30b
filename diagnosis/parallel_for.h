// How the diagnosis spreads independent work (one model prediction per row) over threads
// without the core owning any: the edge passes a ParallelFor, the core calls it.
#pragma once

#include <cstddef>
#include <functional>

namespace gc {

/// Calls body(begin, end) for disjoint ranges covering [0, count), possibly concurrently.
/// `body` must be safe to run concurrently on disjoint ranges.
using ParallelFor =
    std::function<void(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)>;

/// Runs the whole range on the calling thread.
inline ParallelFor serial_for() {
  return [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
    if (count > 0) body(0, count);
  };
}

}  // namespace gc
