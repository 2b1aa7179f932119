#include <cerrno>
#include <ctime>

#include "hal/clock.hpp"

namespace vimg {

std::int64_t SystemClock::now_us() const {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<std::int64_t>(now.tv_sec) * 1'000'000 + now.tv_nsec / 1000;
}

void SystemClock::sleep_until_us(std::int64_t deadline_us) {
  timespec deadline{};
  deadline.tv_sec = static_cast<time_t>(deadline_us / 1'000'000);
  deadline.tv_nsec = static_cast<long>((deadline_us % 1'000'000) * 1000);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, nullptr) == EINTR) {
  }
}

}  // namespace vimg
