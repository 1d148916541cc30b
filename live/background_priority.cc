#include "live/background_priority.h"

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <spdlog/spdlog.h>

namespace gc::live {

void lower_this_thread(int nice) {
  sched_param normal{};
  if (nice >= 19 && pthread_setschedparam(pthread_self(), SCHED_IDLE, &normal) == 0) return;
  pthread_setschedparam(pthread_self(), SCHED_OTHER, &normal);
  if (setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), nice) != 0) {
    spdlog::warn("background thread: nice {} refused; it runs at its process's priority", nice);
  }
}

}  // namespace gc::live
