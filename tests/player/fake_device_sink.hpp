#pragma once
// A test double for a sound card: a DriveSink that paces the stream with its own clock.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "player/drive_sink.hpp"
#include "realtime/clock.hpp"

namespace vimg::test {

// A device that plays `speed` * rate samples per second of CLOCK_MONOTONIC (0.99: its clock runs
// 1 % slow) behind a queue of `queue_samples`: write() blocks while the queue is full, as a sound
// card's does. Keeps every block (reserved ahead, so write() does not allocate).
class FakeDeviceSink final : public DriveSink {
 public:
  FakeDeviceSink(double speed, std::size_t queue_samples) : speed_(speed), queue_samples_(queue_samples) {
    samples.reserve(8000 * 10);
    blocks.reserve(8000 * 10);
  }
  void open(double rate) override {
    rate_ = rate;
    open_ns_ = monotonic_ns();
    written_ = 0;
  }
  void write(std::span<const float> drive, double block_start_time_s) override {
    bool nonzero = false;
    for (float v : drive) nonzero = nonzero || v != 0.0f;
    blocks.push_back({block_start_time_s, drive.size(), monotonic_s(), nonzero});
    samples.insert(samples.end(), drive.begin(), drive.end());
    last_nonzero_.store(nonzero, std::memory_order_release);
    blocks_written_.fetch_add(1, std::memory_order_release);
    written_ += drive.size();
    // Returns when the device has taken all but queue_samples of what was written.
    if (written_ > queue_samples_) {
      const double played_by_s = static_cast<double>(written_ - queue_samples_) / (rate_ * speed_);
      sleep_until_ns(open_ns_ + static_cast<std::int64_t>(played_by_s * 1e9));
    }
  }
  void close() override {}
  bool paces_stream() const override { return true; }
  // The queue in front of the device, as a sound card's buffers.
  double output_latency_s() const override { return rate_ > 0.0 ? static_cast<double>(queue_samples_) / rate_ : 0.0; }

  struct Block {
    double time_s;           // renderer clock
    std::size_t size;
    double written_at_s;     // CLOCK_MONOTONIC when write() was called
    bool nonzero;
  };
  std::vector<float> samples;
  std::vector<Block> blocks;
  // For another thread while the renderer writes (blocks and samples are the writer's until it stops).
  bool last_block_driven() const { return last_nonzero_.load(std::memory_order_acquire); }
  std::uint64_t blocks_written() const { return blocks_written_.load(std::memory_order_acquire); }

 private:
  double speed_;
  std::size_t queue_samples_;
  double rate_ = 0.0;
  std::int64_t open_ns_ = 0;
  std::uint64_t written_ = 0;
  std::atomic<bool> last_nonzero_{false};
  std::atomic<std::uint64_t> blocks_written_{0};
};

}  // namespace vimg::test
