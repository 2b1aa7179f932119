// The render thread never allocates (player/realtime_renderer.hpp), touch-latency compensation on:
// a counting operator new (tests/counting_new: this test binary's, per thread) shows that no block of the real-time
// loop allocates once it runs, with ten fingers moving and the learned predictor on, at 8 and
// 48 kHz. The count is read by the sink on the render thread at each write().
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <thread>

#include "player/realtime_renderer.hpp"
#include "render_support.hpp"
#include "tests/counting_new/counting_new.hpp"

namespace vimg {
namespace {

// Records the render thread's allocations so far at each block.
class CountingSink final : public DriveSink {
 public:
  void open(double) override {}
  void close() override {}
  void write(std::span<const float>, double) override {
    const std::uint64_t n = blocks_.load(std::memory_order_relaxed) + 1;
    if (n == kSettled) at_settled_.store(test::allocations_on_this_thread(), std::memory_order_relaxed);
    if (n >= kSettled) now_.store(test::allocations_on_this_thread(), std::memory_order_relaxed);
    blocks_.store(n, std::memory_order_release);
  }
  std::uint64_t blocks() const { return blocks_.load(std::memory_order_acquire); }
  // Allocations on the render thread from the kSettled-th block to the last one written.
  std::uint64_t allocations_since_settled() const { return now_.load() - at_settled_.load(); }
  static constexpr std::uint64_t kSettled = 20;

 private:
  std::atomic<std::uint64_t> blocks_{0}, at_settled_{0}, now_{0};
};

TEST(LiveAllocation, NoBlockOfTheRealTimeLoopAllocatesWithTenPredictedFingers) {
  const Image img = test::image_of({test::element("s", test::rect_surface(0, 0, 200, 200, 2.0, 0.5, 0.4))});
  for (double rate_hz : {8000.0, 48000.0}) {
    CountingSink sink;
    RealtimeOptions options;
    options.sample_rate_hz = rate_hz;
    options.touch.enabled = true;  // the learned model, the players' default
    RealtimeRenderer r(sink, options);
    r.set_scene(compile_scene(img));
    ASSERT_FALSE(r.start());
    const double t0 = monotonic_s();
    for (int f = 0; f < 10; ++f) r.push_event({t0, f, TouchPhase::down, 20.0 + 15.0 * f, 100.0, 1.0});
    // Moves until 400 blocks (0.4 s) have been rendered: a state, however slowly the machine runs.
    std::uint64_t moves = 0;
    while (sink.blocks() < 400) {
      std::this_thread::sleep_for(std::chrono::milliseconds(4));
      const double t = monotonic_s();
      for (int f = 0; f < 10; ++f) {
        r.push_event({t, f, TouchPhase::move, 20.0 + 15.0 * f + 8.0 * std::cos(15.0 * (t - t0)),
                      100.0 + 8.0 * std::sin(15.0 * (t - t0)), 1.0});
      }
      ++moves;
    }
    for (int f = 0; f < 10; ++f) r.push_event({monotonic_s(), f, TouchPhase::up, 20.0 + 15.0 * f, 100.0, 1.0});
    const std::uint64_t blocks = sink.blocks();
    while (sink.blocks() < blocks + 20) std::this_thread::sleep_for(std::chrono::milliseconds(1));  // the lifts rendered
    const LoopStats stats = r.stats();
    r.stop();
    EXPECT_GT(moves, 10u);
    EXPECT_GT(stats.model_runs, 100u) << "the predictor must have run";
    EXPECT_EQ(sink.allocations_since_settled(), 0u) << rate_hz << " Hz";
  }
}

// The counter counts: a vector grown on this thread is seen.
TEST(LiveAllocation, TheCounterSeesAnAllocation) {
  const std::uint64_t before = test::allocations_on_this_thread();
  std::vector<int>* v = new std::vector<int>(100);
  const std::uint64_t after = test::allocations_on_this_thread();
  delete v;
  EXPECT_GE(after - before, 2u);
}

}  // namespace
}  // namespace vimg
