#include "realtime/realtime_priority.hpp"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <cstring>

namespace vimg {

RealtimePriority request_realtime_priority(int priority) noexcept {
  RealtimePriority result;
  if (priority <= 0) return result;
  result.requested = std::clamp(priority, 1, 99);
  sched_param param{};
  param.sched_priority = result.requested;
  result.error_number = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
  result.granted = result.error_number == 0;
  return result;
}

std::string describe(const RealtimePriority& priority) {
  if (priority.granted) return "SCHED_FIFO " + std::to_string(priority.requested);
  if (priority.requested == 0) return "normal priority";
  std::string text = "normal priority (SCHED_FIFO " + std::to_string(priority.requested) + " refused: ";
  text += std::strerror(priority.error_number);
  text += "; grant CAP_SYS_NICE or an rtprio limit, see docs/hardware.md)";
  return text;
}

}  // namespace vimg
