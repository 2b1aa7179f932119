// The render thread never allocates (player/realtime_renderer.hpp), touch-latency compensation on:
// a counting operator new (this test binary's, per thread) shows that no block of the real-time
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

namespace {
thread_local std::uint64_t allocations_on_this_thread = 0;
}  // namespace

// Every form, so that each allocation is counted and each pair matches (malloc and free underneath;
// under ASan the sanitizer still sees every block through them).
namespace {
void* counted(std::size_t size, std::size_t align = 0) noexcept {
  ++allocations_on_this_thread;
  if (size == 0) size = 1;
  if (align <= alignof(std::max_align_t)) return std::malloc(size);
  return std::aligned_alloc(align, (size + align - 1) / align * align);
}
void* or_throw(void* p) {
  if (p == nullptr) throw std::bad_alloc();
  return p;
}
}  // namespace

void* operator new(std::size_t n) { return or_throw(counted(n)); }
void* operator new[](std::size_t n) { return or_throw(counted(n)); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return counted(n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return counted(n); }
void* operator new(std::size_t n, std::align_val_t a) { return or_throw(counted(n, static_cast<std::size_t>(a))); }
void* operator new[](std::size_t n, std::align_val_t a) { return or_throw(counted(n, static_cast<std::size_t>(a))); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept { return counted(n, static_cast<std::size_t>(a)); }
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept { return counted(n, static_cast<std::size_t>(a)); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }

namespace vimg {
namespace {

// Records the render thread's allocations so far at each block.
class CountingSink final : public DriveSink {
 public:
  void open(double) override {}
  void close() override {}
  void write(std::span<const float>, double) override {
    const std::uint64_t n = blocks_.load(std::memory_order_relaxed) + 1;
    if (n == kSettled) at_settled_.store(allocations_on_this_thread, std::memory_order_relaxed);
    if (n >= kSettled) now_.store(allocations_on_this_thread, std::memory_order_relaxed);
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
  const std::uint64_t before = allocations_on_this_thread;
  std::vector<int>* v = new std::vector<int>(100);
  const std::uint64_t after = allocations_on_this_thread;
  delete v;
  EXPECT_GE(after - before, 2u);
}

}  // namespace
}  // namespace vimg
