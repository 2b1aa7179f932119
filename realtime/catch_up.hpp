#pragma once
// The catch-up rule of a loop paced by absolute deadlines (the haptic loop), as pure functions of
// times on one clock, so that tests check it on a simulated clock:
//   - pace_deadline: a cycle that wakes fewer than `catch_up_periods` periods after its deadline
//     runs at that deadline (the missed cycles run back to back: the loop catches up); further
//     behind, the schedule moves forward to the latest deadline passed (a skip);
//   - overran: a cycle overruns when its work finishes after the next deadline.
// While the loop catches up, every caught-up cycle but the last finishes after its next deadline,
// so one stall gives at most `catch_up_periods` overruns in a row when the cycles' work is short
// (the stalled cycle and the caught-up ones), and a few more when each caught-up cycle's work
// takes a good part of the period. The haptic loop catches up half its overrun limit
// (haptic_catch_up_periods): a single stall, however long, never trips the overrun watchdog,
// whose limit then means that the cycle's work itself does not fit in the period.
//
// Threads: pure functions; safe anywhere, including real-time threads.
#include <cstdint>

namespace vimg {

struct PacedDeadline {
  std::int64_t deadline_ns = 0;  // the deadline the cycle runs at
  bool skipped = false;          // the schedule moved forward
};

// `deadline_ns`: the deadline the loop slept until; `woke_ns`: when it woke; catch_up_periods >= 1.
PacedDeadline pace_deadline(std::int64_t deadline_ns, std::int64_t woke_ns, std::int64_t period_ns,
                            std::int64_t catch_up_periods) noexcept;

// The cycle that ran at `deadline_ns` finished its work after the next deadline.
inline bool overran(std::int64_t deadline_ns, std::int64_t finished_ns, std::int64_t period_ns) noexcept {
  return finished_ns > deadline_ns + period_ns;
}

// How far behind the haptic loop still catches up: half the overrun limit, at least one period
// (at the default limit of 10: 5 periods).
int haptic_catch_up_periods(int overrun_limit_cycles) noexcept;

}  // namespace vimg
