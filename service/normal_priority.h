// Leaving real-time scheduling, for a thread whose work must not hold up the request path.
//
// Under the real-time deployment option (docs/deploy.md, "Real-time priority") the whole process
// starts under SCHED_FIFO, and every thread inherits it. A SCHED_FIFO thread is not preempted by
// another of the same priority: while the service's status publication ran (0.3-1.2 ms once a
// second, measured at 100 requests a second), a request woken on its core waited for it
// (docs/architecture.md, "Where a control loop's tail comes from").
#pragma once

namespace gc::service {

/// Switches the calling thread to SCHED_OTHER (nice 0) if it runs under SCHED_FIFO or SCHED_RR,
/// and returns whether it did. Lowering one's own policy needs no privilege; a thread of normal
/// priority is left as it is (false). Never throws: a thread that cannot be lowered runs on.
bool leave_real_time_priority() noexcept;

}  // namespace gc::service
