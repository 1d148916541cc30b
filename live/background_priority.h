// The priority of a background thread that must never delay the monitor's residuals (the
// diagnosis worker, live/diagnosis_worker.h).
#pragma once

namespace gc::live {

/// Puts the calling thread under the normal policy (a monitor run under SCHED_FIFO, `chrt -f`,
/// must not pass its real-time priority on) at nice `nice` (0-19; Linux: the thread's own nice
/// value, its process's other threads unchanged). At the lowest, 19, it goes under SCHED_IDLE
/// instead: any thread of another policy that wakes on its CPU preempts it at once, where the
/// scheduler may let a nice-19 thread finish its slice first. Logged, not fatal, when refused.
void lower_this_thread(int nice);

}  // namespace gc::live
