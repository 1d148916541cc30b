// The lowest real-time priority, for a thread whose work must not hold up the request path.
//
// Under the real-time deployment option (docs/deploy.md, "Real-time priority") the whole process
// starts under SCHED_FIFO, and every thread inherits the one priority. A SCHED_FIFO thread is not
// preempted by another of the same priority: while the service wrote its status (0.3-1.2 ms of
// CPU once a second at 100 requests a second), a request woken on its core waited for it
// (docs/architecture.md, "Where a control loop's tail comes from").
//
// Why the lowest real-time priority and not a normal one: such a thread takes locks that the
// request path takes too (the statistics', Cyclone's own). A normal thread can be preempted by
// any CPU hog while it holds one, and the real-time thread that needs the lock then waits behind
// the hog: Cyclone's event thread, tried at normal priority, held a receive thread for a whole
// millisecond that way. At the lowest real-time priority the request path preempts it at once,
// and nothing of normal priority does.
#pragma once

namespace gc::service {

/// Sets a SCHED_FIFO or SCHED_RR calling thread to its policy's lowest priority, and returns
/// whether it changed it. Lowering a priority needs no privilege. A thread of normal priority is
/// left as it is (false). Never throws: a thread that cannot be lowered runs on as it was.
bool enter_background_priority() noexcept;

}  // namespace gc::service
