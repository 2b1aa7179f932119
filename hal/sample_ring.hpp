#pragma once
// Single-producer/single-consumer ring of float samples: the renderer pushes, an audio callback
// pops. Lock-free and allocation-free after construction.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <span>
#include <vector>

namespace vimg {

class SampleRing {
 public:
  explicit SampleRing(std::size_t capacity) : buffer_(capacity + 1) {}

  std::size_t capacity() const { return buffer_.size() - 1; }
  std::size_t size() const {
    const auto head = head_.load(std::memory_order_acquire);
    const auto tail = tail_.load(std::memory_order_acquire);
    return head >= tail ? head - tail : head + buffer_.size() - tail;
  }

  // Producer: copies as many samples as fit; returns how many.
  std::size_t push(std::span<const float> samples) {
    const auto head = head_.load(std::memory_order_relaxed);
    const auto tail = tail_.load(std::memory_order_acquire);
    const std::size_t free = (tail + buffer_.size() - head - 1) % buffer_.size();
    const std::size_t count = std::min(free, samples.size());
    for (std::size_t i = 0; i < count; ++i) {
      buffer_[(head + i) % buffer_.size()] = samples[i];
    }
    head_.store((head + count) % buffer_.size(), std::memory_order_release);
    return count;
  }

  // Consumer: fills `out` from the ring; returns how many samples were available.
  std::size_t pop(std::span<float> out) {
    const auto tail = tail_.load(std::memory_order_relaxed);
    const auto head = head_.load(std::memory_order_acquire);
    const std::size_t available = (head + buffer_.size() - tail) % buffer_.size();
    const std::size_t count = std::min(available, out.size());
    for (std::size_t i = 0; i < count; ++i) {
      out[i] = buffer_[(tail + i) % buffer_.size()];
    }
    tail_.store((tail + count) % buffer_.size(), std::memory_order_release);
    return count;
  }

 private:
  std::vector<float> buffer_;
  std::atomic<std::size_t> head_{0};
  std::atomic<std::size_t> tail_{0};
};

}  // namespace vimg
