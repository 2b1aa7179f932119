#pragma once
// Faults seen on the real-time thread, handed to the UI thread without locks or allocation:
// the SPSC ring of small plain records. describe() makes the text later.
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

#include "realtime/spsc_ring.hpp"

namespace vimg {

enum class FaultKind : std::uint8_t {
  transfer_failed,    // a transfer failed after its retries; that write was dropped, playback goes on
  device_gone,        // the device stopped answering; output pauses, reconnection is tried
  reconnected,        // it answers again and was initialized again
  over_current,       // STATUS OC_DETECT: output stopped
  over_temperature,   // STATUS OVER_TEMP: output stopped
  underrun,           // a sample FIFO ran empty
  rest_requested,     // a signal asked for rest: output stopped
};

struct FaultEvent {
  FaultKind kind = FaultKind::transfer_failed;
  int error_number = 0;
  std::int64_t time_us = 0;
};

std::string describe(const FaultEvent& event, const std::string& device_path);

class FaultLog {
 public:
  // Producer side (one thread). Drops the event when the ring is full and counts it.
  void push(FaultEvent event) noexcept {
    if (!ring_.push(event)) dropped_.fetch_add(1, std::memory_order_relaxed);
  }
  // Consumer side (one thread).
  std::optional<FaultEvent> pop() noexcept { return ring_.pop(); }
  std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }

 private:
  SpscRing<FaultEvent> ring_{64};
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace vimg
