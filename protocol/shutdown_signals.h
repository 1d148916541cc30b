// How a DDS program (gearcoupling-service, gearcoupling-monitor) stops on SIGINT and SIGTERM.
#pragma once

#include <signal.h>

namespace gc::protocol {

/// Blocks SIGINT and SIGTERM in every thread (call before starting any) and returns the set, for
/// a thread that waits for them with sigwait: DDS calls are not async-signal-safe.
sigset_t block_shutdown_signals();

}  // namespace gc::protocol
