#pragma once
// The one lock-free single-producer / single-consumer ring of the project, for trivially copyable
// values: touch events and scenes into the renderer, samples into an audio callback, fault codes
// out of a driver, log rows out of the haptic loop.
//
// Capacity is fixed at construction (rounded up to a power of two, at least 2); after that no
// call allocates, locks or blocks. push() fails when full: the producer decides what to drop.
//
// Threads: exactly one producer thread (push, push_some) and one consumer thread (pop, pop_some)
// at a time; size() and capacity() from any thread.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>

namespace vimg {

template <class T>
class SpscRing {
  static_assert(std::is_trivially_copyable_v<T>);

 public:
  explicit SpscRing(std::size_t capacity) {
    std::size_t n = 2;
    while (n < capacity) n *= 2;
    mask_ = n - 1;
    slots_ = std::make_unique<T[]>(n);
  }
  SpscRing(const SpscRing&) = delete;
  SpscRing& operator=(const SpscRing&) = delete;

  // Producer. False when full (the value is not stored).
  bool push(const T& value) noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_.load(std::memory_order_acquire) > mask_) return false;
    slots_[head & mask_] = value;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  // Producer: stores as many values from the front of `values` as fit; returns how many.
  std::size_t push_some(std::span<const T> values) noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    const std::size_t free = capacity() - (head - tail_.load(std::memory_order_acquire));
    const std::size_t count = std::min(free, values.size());
    for (std::size_t i = 0; i < count; ++i) slots_[(head + i) & mask_] = values[i];
    head_.store(head + count, std::memory_order_release);
    return count;
  }

  // Consumer. Empty when there is nothing to take.
  std::optional<T> pop() noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return std::nullopt;
    T value = slots_[tail & mask_];
    tail_.store(tail + 1, std::memory_order_release);
    return value;
  }

  // Consumer: fills the front of `out`; returns how many values were taken.
  std::size_t pop_some(std::span<T> out) noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    const std::size_t available = head_.load(std::memory_order_acquire) - tail;
    const std::size_t count = std::min(available, out.size());
    for (std::size_t i = 0; i < count; ++i) out[i] = slots_[(tail + i) & mask_];
    tail_.store(tail + count, std::memory_order_release);
    return count;
  }

  // Values waiting; exact on either side's own thread, a snapshot elsewhere.
  std::size_t size() const noexcept {
    const std::size_t tail = tail_.load(std::memory_order_acquire);
    return head_.load(std::memory_order_acquire) - tail;
  }
  std::size_t capacity() const noexcept { return mask_ + 1; }

 private:
  std::unique_ptr<T[]> slots_;
  std::size_t mask_ = 0;
  alignas(64) std::atomic<std::size_t> head_{0};  // written by the producer
  alignas(64) std::atomic<std::size_t> tail_{0};  // written by the consumer
};

}  // namespace vimg
