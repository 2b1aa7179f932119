// The catch-up rule of the haptic loop on a simulated clock: stalls, one or many close together, of
// any length, never give the overrun limit's worth of overruns in a row, while work that does not
// fit in the period does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>

#include "realtime/catch_up.hpp"
#include "realtime/clock.hpp"

namespace vimg {
namespace {

constexpr std::int64_t kPeriodUs = 1000;  // 1 kHz
constexpr int kOverrunLimit = 10;         // SafetySettings' default

struct ScheduleRun {
  int longest_overrun_streak = 0;  // what the overrun watchdog counts: work_overran in a row
  int behind = 0;                  // what the telemetry counts: cycles that finished after the next deadline
  int skips = 0;
  bool faulted = false;  // the streak reached the limit
};

// The haptic loop's schedule on a fake clock, through the functions HapticLoop::run and the safety
// stack call (realtime/catch_up.hpp): sleep until the deadline, wake `wake_delay_us(n)` late, pace
// the cycle, work `work_us(n)`, and count overruns in a row as the watchdog does.
ScheduleRun run_schedule(int cycles, const std::function<std::int64_t(int)>& wake_delay_us,
                         const std::function<std::int64_t(int)>& work_us) {
  FakeClock clock(1'000'000);
  PacedSchedule schedule{kPeriodUs * 1000, haptic_catch_up_periods(kOverrunLimit), clock.now_us() * 1000};
  ScheduleRun run;
  int streak = 0;
  for (int n = 0; n < cycles; ++n) {
    clock.sleep_until_us(next_deadline_ns(schedule) / 1000);
    clock.advance_us(wake_delay_us(n));
    const std::int64_t woke_ns = clock.now_us() * 1000;
    if (on_wake(schedule, woke_ns).skipped) ++run.skips;
    clock.advance_us(work_us(n));
    const CycleEnd end = on_finish(schedule, woke_ns, clock.now_us() * 1000);
    if (end.behind) ++run.behind;
    // The safety stack counts the previous cycle's overrun at the next cycle; counted here at once.
    streak = count_overruns_in_row(streak, end.work_overran);
    run.longest_overrun_streak = std::max(run.longest_overrun_streak, streak);
    run.faulted = run.faulted || overrun_watchdog_trips(streak, kOverrunLimit);
  }
  return run;
}

std::function<std::int64_t(int)> once_at(int cycle, std::int64_t us, std::int64_t otherwise_us = 0) {
  return [=](int n) { return n == cycle ? us : otherwise_us; };
}

TEST(CatchUp, ACycleRunsAtItsDeadlineWhileTheLoopIsLessThanTheLimitBehind) {
  const std::int64_t p = 1'000'000;
  EXPECT_EQ(pace_deadline(10 * p, 10 * p, p, 5).deadline_ns, 10 * p);
  const PacedDeadline behind = pace_deadline(10 * p, 14 * p + p / 2, p, 5);
  EXPECT_EQ(behind.deadline_ns, 10 * p);
  EXPECT_FALSE(behind.skipped);
  // Five periods behind: the schedule moves to the latest deadline passed.
  const PacedDeadline far = pace_deadline(10 * p, 15 * p + p / 2, p, 5);
  EXPECT_EQ(far.deadline_ns, 15 * p);
  EXPECT_TRUE(far.skipped);
  EXPECT_TRUE(pace_deadline(10 * p, 15 * p, p, 5).skipped);
  // Woken early (a clock read before the deadline) is on time.
  EXPECT_FALSE(pace_deadline(10 * p, 9 * p, p, 5).skipped);
}

TEST(CatchUp, TheHapticLoopCatchesUpHalfItsOverrunLimit) {
  EXPECT_EQ(haptic_catch_up_periods(10), 5);
  EXPECT_EQ(haptic_catch_up_periods(11), 5);
  EXPECT_EQ(haptic_catch_up_periods(3), 1);
  EXPECT_EQ(haptic_catch_up_periods(1), 1);
  EXPECT_EQ(haptic_catch_up_periods(0), 1);
}

TEST(CatchUp, OverrunMeansFinishingAfterTheNextDeadline) {
  EXPECT_FALSE(overran(0, 1000, 1000));
  EXPECT_TRUE(overran(0, 1001, 1000));
}

// The case the issue names: one stall of 10.5 periods inside a cycle's work, under the default
// limit. Catching up 10 periods (the earlier rule) gave 10 overruns in a row and the fault.
TEST(CatchUp, OneStallOfTenAndAHalfPeriodsDoesNotFault) {
  const ScheduleRun run = run_schedule(100, once_at(-1, 0), once_at(20, 10 * kPeriodUs + kPeriodUs / 2, 20));
  EXPECT_FALSE(run.faulted);
  EXPECT_EQ(run.longest_overrun_streak, 1);  // the stalled cycle; the loop skips
  EXPECT_EQ(run.skips, 1);
}

TEST(CatchUp, NoSingleStallOfAnyLengthReachesTheOverrunLimit) {
  // Stalls from 0 to 40 periods in 1/20 period steps, in the work of a cycle or as a late
  // wake-up, with each cycle's own work from nothing to 40 % of the period.
  for (const std::int64_t work_us : {std::int64_t{0}, std::int64_t{20}, std::int64_t{200}, std::int64_t{400}}) {
    for (std::int64_t stall_us = 0; stall_us <= 40 * kPeriodUs; stall_us += kPeriodUs / 20) {
      const ScheduleRun in_work = run_schedule(80, once_at(-1, 0), once_at(30, stall_us, work_us));
      ASSERT_LT(in_work.longest_overrun_streak, kOverrunLimit) << "stall " << stall_us << " us in the work, work " << work_us;
      const ScheduleRun late_wake = run_schedule(80, once_at(30, stall_us), once_at(-1, 0, work_us));
      ASSERT_LT(late_wake.longest_overrun_streak, kOverrunLimit) << "woke " << stall_us << " us late, work " << work_us;
      if (work_us == 0) {
        // Short work: at most the catch-up bound in a row.
        ASSERT_LE(in_work.longest_overrun_streak, haptic_catch_up_periods(kOverrunLimit)) << stall_us;
      }
    }
  }
}

// Stalls close together, as at the start of a loop on a busy machine: with each cycle's work short,
// however many wake-ups come late by up to 4.9 periods, every few cycles, the loop is behind on
// many cycles in a row but no cycle's work overran. Counting the cycles that finish behind (the
// earlier watchdog) faulted here.
TEST(CatchUp, StallsCloseTogetherNeverTripTheWatchdog) {
  for (const int every : {1, 2, 3, 4, 5}) {
    for (const std::int64_t late_us : {2 * kPeriodUs, 3 * kPeriodUs + 500, 4 * kPeriodUs + 900}) {
      const ScheduleRun run = run_schedule(200, [=](int n) { return n % every == 0 && n < 60 ? late_us : 0; },
                                           once_at(-1, 0, 20));
      EXPECT_EQ(run.longest_overrun_streak, 0) << "every " << every << ", " << late_us << " us late";
      EXPECT_FALSE(run.faulted);
    }
  }
  // Stalls of two periods inside the work of every other cycle: each stalled cycle overran, the
  // cycles between did not; ten behind in a row.
  const ScheduleRun in_work = run_schedule(40, once_at(-1, 0), [](int n) { return n < 12 && n % 2 == 0 ? 2 * kPeriodUs : 20; });
  EXPECT_EQ(in_work.longest_overrun_streak, 1);
  EXPECT_GE(in_work.behind, 10);
}

TEST(CatchUp, ALongStallSkipsInsteadOfBurstingAndTheLoopKeepsItsSchedule) {
  const ScheduleRun run = run_schedule(100, once_at(-1, 0), once_at(10, 50 * kPeriodUs, 20));
  EXPECT_EQ(run.skips, 1);
  EXPECT_EQ(run.longest_overrun_streak, 1);
  // A short stall is caught up: no skip; the stalled cycle and the two caught up behind it finish
  // late, and only the stalled one's work did not fit.
  const ScheduleRun short_stall = run_schedule(100, once_at(-1, 0), once_at(10, 3 * kPeriodUs + 500, 20));
  EXPECT_EQ(short_stall.skips, 0);
  EXPECT_EQ(short_stall.behind, 3);
  EXPECT_EQ(short_stall.longest_overrun_streak, 1);
}

TEST(CatchUp, WorkThatDoesNotFitInThePeriodStillTripsTheWatchdog) {
  for (const std::int64_t work_us : {kPeriodUs + 1, kPeriodUs + 100, 3 * kPeriodUs, 20 * kPeriodUs}) {
    const ScheduleRun run = run_schedule(kOverrunLimit, once_at(-1, 0), once_at(-1, 0, work_us));
    EXPECT_TRUE(run.faulted) << work_us;
    EXPECT_EQ(run.longest_overrun_streak, kOverrunLimit) << work_us;
  }
}

}  // namespace
}  // namespace vimg
