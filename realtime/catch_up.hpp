#pragma once
// The catch-up rule of a loop paced by absolute deadlines (the haptic loop), as pure functions of
// times on one clock, so that tests check it on a simulated clock:
//   - pace_deadline: a cycle that wakes fewer than `catch_up_periods` periods after its deadline
//     runs at that deadline (the missed cycles run back to back: the loop catches up); further
//     behind, the schedule moves forward to the latest deadline passed (a skip);
//   - overran: a cycle overruns when its work finishes after the next deadline (the telemetry's
//     count: how often the loop was behind its schedule);
//   - work_overran: the cycle's own work, from its wake-up to its end, took longer than a period
//     (what the overrun watchdog counts).
// While the loop catches up, every caught-up cycle but the last finishes after its next deadline,
// so one stall gives up to `catch_up_periods` overruns in a row (the stalled cycle and the
// caught-up ones), and a second stall while the loop catches up goes on counting: two or three
// wake-ups a few periods late (a thread that has just started, a machine busy elsewhere, at normal
// priority) made ten in a row although every cycle's work took microseconds. The watchdog's
// limit is meant for work that does not fit in the period, so it counts work_overran: a stall
// inside a cycle's work is one, a late wake-up and the cycles caught up after it are none. The
// haptic loop catches up half its overrun limit (haptic_catch_up_periods) and skips beyond.
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

// The cycle that woke at `woke_ns` finished its work more than one period later.
inline bool work_overran(std::int64_t woke_ns, std::int64_t finished_ns, std::int64_t period_ns) noexcept {
  return finished_ns - woke_ns > period_ns;
}

// How far behind the haptic loop still catches up: half the overrun limit, at least one period
// (at the default limit of 10: 5 periods).
int haptic_catch_up_periods(int overrun_limit_cycles) noexcept;

}  // namespace vimg
