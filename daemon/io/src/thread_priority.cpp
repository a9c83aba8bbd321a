#include "cyber/daemon/io/thread_priority.hpp"

#include <pthread.h>
#include <sched.h>

namespace cyber::daemon::io {

int requestRealtimePriority(int priority) {
  sched_param param{};
  param.sched_priority = priority;
  return pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0 ? priority : 0;
}

void useNormalScheduling() {
  sched_param param{};
  param.sched_priority = 0;
  pthread_setschedparam(pthread_self(), SCHED_OTHER, &param);
}

}  // namespace cyber::daemon::io
