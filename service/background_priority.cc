#include "service/background_priority.h"

#include <pthread.h>
#include <sched.h>

namespace gc::service {

bool enter_background_priority() noexcept {
  int policy = 0;
  sched_param param{};
  if (pthread_getschedparam(pthread_self(), &policy, &param) != 0) return false;
  if (policy != SCHED_FIFO && policy != SCHED_RR) return false;
  const int lowest = sched_get_priority_min(policy);
  if (param.sched_priority <= lowest) return false;
  param.sched_priority = lowest;
  return pthread_setschedparam(pthread_self(), policy, &param) == 0;
}

}  // namespace gc::service
