// gc_sched_slice SLICE_US PROGRAM [ARG...]: runs PROGRAM, still under SCHED_OTHER, with a
// scheduler slice of SLICE_US microseconds, which it and every thread it starts inherit. No
// privilege is needed (Linux 6.12 and later: EEVDF's custom slice, sched_attr::sched_runtime).
//
// For bench/control_loop.sh's "slice" pass (docs/architecture.md, "Where a control loop's tail
// comes from"): EEVDF orders tasks by virtual deadline, eligible time plus slice, so a woken
// thread with a 100 us slice should preempt a CPU hog with the default 0.75-3 ms at once, where
// with the default it may wait for the hog's slice to end. The service, its client and ddsperf,
// the anchor, all run under it, so the comparison stays fair.
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

// The kernel's struct sched_attr (include/uapi/linux/sched/types.h); glibc 2.36 has no wrapper.
struct SchedAttr {
  std::uint32_t size;
  std::uint32_t sched_policy;
  std::uint64_t sched_flags;
  std::int32_t sched_nice;
  std::uint32_t sched_priority;
  std::uint64_t sched_runtime;  // for SCHED_OTHER: the slice (ns)
  std::uint64_t sched_deadline;
  std::uint64_t sched_period;
  std::uint32_t sched_util_min;
  std::uint32_t sched_util_max;
};

// The range the kernel takes for a slice (kernel/sched/syscalls.c clamps to it), in us.
constexpr long kMinSliceUs = 100;
constexpr long kMaxSliceUs = 100'000;

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s SLICE_US PROGRAM [ARG...]\n", argv[0]);
    return 2;
  }
  char* end = nullptr;
  const long slice_us = std::strtol(argv[1], &end, 10);
  if (end == argv[1] || *end != '\0' || slice_us < kMinSliceUs || slice_us > kMaxSliceUs) {
    std::fprintf(stderr, "%s: SLICE_US \"%s\" is not a whole number of microseconds in [%ld, %ld]\n",
                 argv[0], argv[1], kMinSliceUs, kMaxSliceUs);
    return 2;
  }
  if (sched_getscheduler(0) != SCHED_OTHER) {
    std::fprintf(stderr, "%s: not under SCHED_OTHER: a real-time policy has no slice\n", argv[0]);
    return 2;
  }
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, 0);
  SchedAttr attr{};
  attr.size = sizeof attr;
  attr.sched_policy = SCHED_OTHER;
  attr.sched_nice = errno == 0 ? nice : 0;
  attr.sched_runtime = static_cast<std::uint64_t>(slice_us) * 1000U;
  if (syscall(SYS_sched_setattr, 0, &attr, 0U) != 0) {
    std::fprintf(stderr, "%s: sched_setattr: %s\n", argv[0], std::strerror(errno));
    return 2;
  }
  execvp(argv[2], argv + 2);
  std::fprintf(stderr, "%s: cannot run %s: %s\n", argv[0], argv[2], std::strerror(errno));
  return 127;
}
