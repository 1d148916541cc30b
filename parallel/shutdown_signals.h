// SIGINT and SIGTERM for the long-running programs (service, dashboard): blocked in every
// thread and taken by one thread with sigwait, so that a shutdown runs as ordinary code: DDS
// calls are not async-signal-safe.
#pragma once

#include <signal.h>

namespace gc::parallel {

/// Blocks SIGINT and SIGTERM in the calling thread and every thread it starts afterwards (call
/// before starting any) and returns the set, for a thread that waits for them with sigwait.
sigset_t block_shutdown_signals();

}  // namespace gc::parallel
