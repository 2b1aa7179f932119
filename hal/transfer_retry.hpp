#pragma once
// The render-thread side of a device's transfers, the same for every driver (DRV2605L, BOS1901,
// HID haptics):
//   retry_transfer()   tries again after a transient error (NACK, EIO, EAGAIN, ...) with
//                      exponential backoff, waiting on the device's clock; 0 or the last errno;
//   TransferAccount    turns results into fault codes: a failure that persists is reported once
//                      per episode (transfer_failed); ENODEV-like errors, or failures_until_gone
//                      failures in a row, mean the device is gone: device_gone is posted and the
//                      device link goes down, so the service thread owns the device from then on.
//
// Threads: the render thread only. Neither allocates, locks nor throws (the attempt must not).
#include <cstdint>

#include "hal/device_error.hpp"
#include "hal/device_link.hpp"
#include "hal/fault_log.hpp"
#include "realtime/clock.hpp"

namespace vimg {

template <typename Attempt>
int retry_transfer(Clock& clock, int max_retries, std::int64_t first_backoff_us, Attempt&& attempt) {
  std::int64_t backoff_us = first_backoff_us;
  for (int tries = 0;; ++tries) {
    const int error = attempt();
    if (error == 0 || !transient_error(error) || tries >= max_retries) return error;
    clock.sleep_for_us(backoff_us);  // wait on the device, then try again
    backoff_us *= 2;
  }
}

struct TransferAccount {
  int consecutive_failures = 0;
  bool failure_reported = false;  // transfer_failed posted in this episode
  bool gone = false;

  // True when `error` is 0. Otherwise posts what it means (see above) and returns false.
  bool account(int error, int failures_until_gone, FaultLog& faults, DeviceLink& link, const Clock& clock) noexcept {
    if (error == 0) {
      consecutive_failures = 0;
      failure_reported = false;
      return true;
    }
    ++consecutive_failures;
    if (device_gone_error(error) || consecutive_failures >= failures_until_gone) {
      gone = true;
      faults.push({FaultKind::device_gone, error, clock.now_us()});
      link.take_down();  // after the push and the last transfer: the service owns the device now
    } else if (!failure_reported) {
      failure_reported = true;
      faults.push({FaultKind::transfer_failed, error, clock.now_us()});
    }
    return false;
  }
  // After a reconnection: a fresh episode.
  void reset() noexcept { *this = TransferAccount{}; }
};

}  // namespace vimg
