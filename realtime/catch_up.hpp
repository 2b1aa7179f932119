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
// The haptic loop (player/haptic/haptic_loop.cpp) runs its schedule through PacedSchedule and the
// safety stack (player/haptic/safety_stack.cpp) counts through count_overruns_in_row and
// overrun_watchdog_trips; tests/realtime/catch_up_test.cpp drives the same functions on a fake clock.
//
// Threads: pure functions over caller-owned state; safe anywhere, including real-time threads.
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

// A paced loop's schedule (caller-owned). A cycle: next_deadline_ns, sleep until it, on_wake with
// the time woken (the cycle then runs at schedule.deadline_ns), the work, on_finish.
struct PacedSchedule {
  std::int64_t period_ns = 0;
  std::int64_t catch_up_periods = 1;
  std::int64_t deadline_ns = 0;  // the current cycle's deadline (the start time before the first)
};

// The next cycle's deadline, to sleep until.
inline std::int64_t next_deadline_ns(PacedSchedule& schedule) noexcept {
  schedule.deadline_ns += schedule.period_ns;
  return schedule.deadline_ns;
}

// Woken at `woke_ns`: the cycle is paced (pace_deadline) and the schedule follows.
inline PacedDeadline on_wake(PacedSchedule& schedule, std::int64_t woke_ns) noexcept {
  const PacedDeadline paced = pace_deadline(schedule.deadline_ns, woke_ns, schedule.period_ns, schedule.catch_up_periods);
  schedule.deadline_ns = paced.deadline_ns;
  return paced;
}

struct CycleEnd {
  bool behind = false;        // finished after the next deadline (overran: the telemetry's count)
  bool work_overran = false;  // its own work took longer than a period (the watchdog's count)
};

inline CycleEnd on_finish(const PacedSchedule& schedule, std::int64_t woke_ns, std::int64_t finished_ns) noexcept {
  return {overran(schedule.deadline_ns, finished_ns, schedule.period_ns),
          work_overran(woke_ns, finished_ns, schedule.period_ns)};
}

// The overrun watchdog: cycles in a row whose work overran, and whether that many trip a limit.
inline int count_overruns_in_row(int overruns_in_row, bool previous_overran) noexcept {
  return previous_overran ? overruns_in_row + 1 : 0;
}
inline bool overrun_watchdog_trips(int overruns_in_row, int overrun_limit_cycles) noexcept {
  return overruns_in_row >= overrun_limit_cycles;
}

// How far behind the haptic loop still catches up: half the overrun limit, at least one period
// (at the default limit of 10: 5 periods).
int haptic_catch_up_periods(int overrun_limit_cycles) noexcept;

}  // namespace vimg
