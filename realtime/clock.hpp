#pragma once
// The one clock of the real-time core: CLOCK_MONOTONIC, read with monotonic_ns() / monotonic_s(),
// and absolute sleeps (clock_nanosleep with TIMER_ABSTIME, restarted on EINTR), so that a loop
// paced by deadlines never accumulates lateness.
//
// Drivers that wait (the 250 us after EN, calibration polling, retry backoff) take a Clock&, so
// that tests can check the waits without real time: SystemClock is this clock, FakeClock the
// test double.
//
// Threads: every function here is thread-safe, allocation-free and lock-free. FakeClock is for
// one thread at a time.
#include <cstdint>

namespace vimg {

// Nanoseconds on CLOCK_MONOTONIC.
std::int64_t monotonic_ns() noexcept;
// Seconds on CLOCK_MONOTONIC: the time base of TouchEvent, the renderers and the haptic loop.
double monotonic_s() noexcept;
// Returns at or after the absolute deadline on CLOCK_MONOTONIC; at once if it has passed.
void sleep_until_ns(std::int64_t deadline_ns) noexcept;

class Clock {
 public:
  virtual ~Clock() = default;
  // Microseconds since an arbitrary fixed origin; never goes backwards.
  virtual std::int64_t now_us() const = 0;
  // Returns at or after `deadline_us` (absolute, on this clock). Returns at once if it has passed.
  virtual void sleep_until_us(std::int64_t deadline_us) = 0;

  void sleep_for_us(std::int64_t duration_us) { sleep_until_us(now_us() + duration_us); }
};

// CLOCK_MONOTONIC (monotonic_ns / sleep_until_ns).
class SystemClock final : public Clock {
 public:
  std::int64_t now_us() const override { return monotonic_ns() / 1000; }
  void sleep_until_us(std::int64_t deadline_us) override { sleep_until_ns(deadline_us * 1000); }
};

// Test double: time moves only when someone sleeps or calls advance_us().
class FakeClock final : public Clock {
 public:
  explicit FakeClock(std::int64_t start_us = 0) : now_us_(start_us) {}
  std::int64_t now_us() const override { return now_us_; }
  void sleep_until_us(std::int64_t deadline_us) override {
    if (deadline_us > now_us_) {
      total_slept_us_ += deadline_us - now_us_;
      now_us_ = deadline_us;
    }
  }
  void advance_us(std::int64_t duration_us) { now_us_ += duration_us; }
  std::int64_t total_slept_us() const { return total_slept_us_; }

 private:
  std::int64_t now_us_ = 0;
  std::int64_t total_slept_us_ = 0;
};

}  // namespace vimg
