#include "service/normal_priority.h"

#include <pthread.h>
#include <sched.h>

namespace gc::service {

bool leave_real_time_priority() noexcept {
  int policy = 0;
  sched_param param{};
  if (pthread_getschedparam(pthread_self(), &policy, &param) != 0) return false;
  if (policy != SCHED_FIFO && policy != SCHED_RR) return false;
  param.sched_priority = 0;
  return pthread_setschedparam(pthread_self(), SCHED_OTHER, &param) == 0;
}

}  // namespace gc::service
