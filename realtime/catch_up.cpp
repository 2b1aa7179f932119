#include "realtime/catch_up.hpp"

namespace vimg {

PacedDeadline pace_deadline(std::int64_t deadline_ns, std::int64_t woke_ns, std::int64_t period_ns,
                            std::int64_t catch_up_periods) noexcept {
  const std::int64_t late_ns = woke_ns - deadline_ns;
  if (period_ns <= 0 || late_ns < period_ns * (catch_up_periods < 1 ? 1 : catch_up_periods)) return {deadline_ns, false};
  return {deadline_ns + late_ns / period_ns * period_ns, true};
}

int haptic_catch_up_periods(int overrun_limit_cycles) noexcept {
  return overrun_limit_cycles / 2 < 1 ? 1 : overrun_limit_cycles / 2;
}

}  // namespace vimg
