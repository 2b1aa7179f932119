#pragma once
// Time for drivers: a monotonic clock that can also wait. Drivers take a Clock& so that tests can
// check waits (the 250 us after EN, calibration polling, retry backoff) without real time.
#include <cstdint>

namespace vimg {

class Clock {
 public:
  virtual ~Clock() = default;
  // Microseconds since an arbitrary fixed origin; never goes backwards.
  virtual std::int64_t now_us() const = 0;
  // Returns at or after `deadline_us` (absolute, on this clock). Returns at once if it has passed.
  virtual void sleep_until_us(std::int64_t deadline_us) = 0;

  void sleep_for_us(std::int64_t duration_us) { sleep_until_us(now_us() + duration_us); }
};

// CLOCK_MONOTONIC with clock_nanosleep(TIMER_ABSTIME).
class SystemClock final : public Clock {
 public:
  std::int64_t now_us() const override;
  void sleep_until_us(std::int64_t deadline_us) override;
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
