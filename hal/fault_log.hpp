#pragma once
// Faults seen on the real-time thread, handed to the UI thread without locks or allocation:
// a single-producer/single-consumer ring of small plain records. describe() makes the text later.
#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

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
    const auto head = head_.load(std::memory_order_relaxed);
    const auto next = (head + 1) % kCapacity;
    if (next == tail_.load(std::memory_order_acquire)) {
      dropped_.fetch_add(1, std::memory_order_relaxed);
      return;
    }
    events_[head] = event;
    head_.store(next, std::memory_order_release);
  }
  // Consumer side (one thread).
  std::optional<FaultEvent> pop() noexcept {
    const auto tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) {
      return std::nullopt;
    }
    const FaultEvent event = events_[tail];
    tail_.store((tail + 1) % kCapacity, std::memory_order_release);
    return event;
  }
  std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }

 private:
  static constexpr std::size_t kCapacity = 64;
  std::array<FaultEvent, kCapacity> events_{};
  std::atomic<std::size_t> head_{0};
  std::atomic<std::size_t> tail_{0};
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace vimg
