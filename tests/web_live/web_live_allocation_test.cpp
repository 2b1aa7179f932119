// The page's live renderer allocates nothing per block (issue 44): web/wasm/web_renderer.cpp, the
// C++ behind the AudioWorklet's vimg_live_event_at and vimg_live_render, built natively into this
// test (tests/CMakeLists.txt), driven as the worklet drives it: 128-frame blocks at 48 kHz, ten
// fingers circling on the smiley at 120 Hz events with the learned predictor on (the page's
// default), events queued with their own time, some already past and some due inside the next
// block, fingers that rest in silence and that lift and land again. A counting operator new (this
// binary's, tests/counting_new, as tests/player/live_allocation_test.cpp's) counts every allocation of each block's
// calls after a warm-up of kWarmUpBlocks; the count must be zero. The stream's clock is the
// samples': nothing here depends on the machine's timing.
//
// Seen to fail: with `std::vector<float> scratch(frames);` added at the top of
// WebRenderer::live_render, NoBlockAllocatesWithTenPredictedFingers fails ("1 allocation per
// block", first at block kWarmUpBlocks). The renderer is built here at the tests' -O0, so no
// allocation is optimised away; the wasm uses Emscripten's libc++ instead of libstdc++, which this
// test does not see.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "storage/image_io.hpp"
#include "storage/vsc/vsc_image.hpp"
#include "web/wasm/web_renderer.hpp"
#include "tests/counting_new/counting_new.hpp"

namespace vimg {
namespace {

constexpr double kRateHz = 48000.0;          // the AudioContext's rate
constexpr std::size_t kBlockFrames = 128;    // the AudioWorklet's render quantum
constexpr double kEventRateHz = 120.0;       // a 120 Hz touch panel, every finger each time
constexpr double kHorizonS = 0.035;          // the page's touch default, 25 ms + the output's latency
constexpr double kLateS = 0.012;             // how late the even fingers' events reach the worklet
constexpr int kFingers = 10;
constexpr std::size_t kWarmUpBlocks = 40;    // 107 ms: the block buffer sized, every finger down
constexpr std::size_t kBlocks = 6000;        // 16 s of stream

// The smiley as the page gets it: `vimg serve`'s .vsc bytes, read back by the renderer.
std::string smiley_vsc() {
  const LoadResult loaded = load_image_file(std::filesystem::path(VIMG_SOURCE_DIR) / "assets/examples/smiley.vimg");
  if (!loaded.image) return {};
  VscImage v;
  v.image = *loaded.image;
  return write_vsc(v);
}

// Finger f's event k (time k / kEventRateHz), as bench/ten_finger_gesture.py places them: a 2 x 5
// grid on the face, each circling its own centre (radius 8 mm) at 120 mm/s. Each finger is off the
// glass 100 ms every 3 s and rests (no events, the silence fade) 200 ms every 2 s, staggered.
bool lifted(int f, std::int64_t k) { return k >= 0 && (k + 30 * f) % 360 < 12; }
bool resting(int f, std::int64_t k) { return (k + 17 * f) % 240 >= 216; }
// False when finger f sends nothing at event k.
bool event_of(int f, std::int64_t k, TouchEvent& e) {
  const bool up_now = lifted(f, k);
  const bool up_before = k == 0 || lifted(f, k - 1);
  if (up_now && up_before) return false;
  e.phase = up_now ? TouchPhase::up : up_before ? TouchPhase::down : TouchPhase::move;
  if (e.phase == TouchPhase::move && resting(f, k)) return false;
  const double t = static_cast<double>(k) / kEventRateHz;
  const double a = (120.0 / 8.0) * t + f * 0.7;
  e.time_s = t;
  e.finger = f;
  e.x_mm = 25.0 + 20.0 * (f % 2) + 8.0 * std::cos(a);
  e.y_mm = 46.0 + 12.0 * (f / 2) + 8.0 * std::sin(a);
  e.pressure = 1.0;
  return true;
}

// The worklet's side: before each block, the events that have reached it are queued with their own
// time. Odd fingers' events arrive before the block they fall in (applied inside it), even fingers'
// kLateS after their time (applied at the block's first sample, stamped with their own time).
class Feeder {
 public:
  void before_block(WebRenderer& r, double block_start_s, double block_end_s) {
    for (int parity = 0; parity < 2; ++parity) {
      for (;;) {
        const double t = static_cast<double>(next_[parity]) / kEventRateHz;
        if (parity == 1 ? t >= block_end_s : t + kLateS > block_start_s) break;
        for (int f = parity; f < kFingers; f += 2) {
          TouchEvent e;
          if (event_of(f, next_[parity], e)) {
            r.live_event_at(e);
            ++sent_;
          }
        }
        ++next_[parity];
      }
    }
  }
  std::uint64_t sent() const { return sent_; }

 private:
  std::int64_t next_[2] = {0, 0};
  std::uint64_t sent_ = 0;
};

// One renderer driven for kBlocks blocks, the allocations of each block's calls counted.
struct LiveRun {
  WebRenderer renderer;
  Feeder feeder;
  std::vector<float> drive;
  std::uint64_t allocations_after_warm_up = 0;
  std::size_t first_allocating_block = kBlocks;
  std::size_t most_contacts = 0;

  bool start(const std::string& vsc, double horizon_s) {
    drive.reserve(kBlocks * kBlockFrames);
    if (!renderer.load_vsc(vsc)) return false;
    renderer.live_set_prediction(horizon_s);
    renderer.live_start(kRateHz);
    return true;
  }
  void block(std::size_t b) {
    const double start_s = renderer.live_time_s();
    const std::uint64_t before = test::allocations_on_this_thread();
    feeder.before_block(renderer, start_s, start_s + static_cast<double>(kBlockFrames) / kRateHz);
    const std::vector<float>& out = renderer.live_render(kBlockFrames);
    const std::size_t contacts = renderer.live_contacts();
    const std::uint64_t made = test::allocations_on_this_thread() - before;
    if (b >= kWarmUpBlocks && made > 0) {
      allocations_after_warm_up += made;
      first_allocating_block = std::min(first_allocating_block, b);
    }
    most_contacts = std::max(most_contacts, contacts);
    drive.insert(drive.end(), out.begin(), out.end());  // reserved: no allocation (and not counted)
  }
};

TEST(WebLiveAllocation, NoBlockAllocatesWithTenPredictedFingers) {
  const std::string vsc = smiley_vsc();
  ASSERT_FALSE(vsc.empty());
  LiveRun on;
  LiveRun off;  // the same stream without prediction: the drive must differ, so the predictor ran
  ASSERT_TRUE(on.start(vsc, kHorizonS)) << on.renderer.error();
  ASSERT_TRUE(off.start(vsc, 0.0)) << off.renderer.error();
  ASSERT_GT(on.renderer.live_prediction_horizon_s(), 0.0);
  for (std::size_t b = 0; b < kBlocks; ++b) {
    on.block(b);
    off.block(b);
  }
  EXPECT_EQ(on.allocations_after_warm_up, 0u)
      << static_cast<double>(on.allocations_after_warm_up) / static_cast<double>(kBlocks - kWarmUpBlocks)
      << " allocations per block, first at block " << on.first_allocating_block;
  EXPECT_EQ(off.allocations_after_warm_up, 0u) << "prediction off, first at block " << off.first_allocating_block;

  // What ran: ten fingers' events (every lift, landing and silence included), all applied; ten
  // fingers or more in contact with primitives at once; a drive that sounds and that prediction moved.
  EXPECT_GT(on.feeder.sent(), static_cast<std::uint64_t>(kFingers * 16 * kEventRateHz * 0.8));
  EXPECT_EQ(on.renderer.live_queued_events(), 0u);
  EXPECT_GE(on.most_contacts, static_cast<std::size_t>(kFingers));
  float peak = 0.0f;
  float moved = 0.0f;
  ASSERT_EQ(on.drive.size(), off.drive.size());
  for (std::size_t i = 0; i < on.drive.size(); ++i) {
    peak = std::max(peak, std::abs(on.drive[i]));
    moved = std::max(moved, std::abs(on.drive[i] - off.drive[i]));
  }
  EXPECT_GT(peak, 0.05f);
  EXPECT_GT(moved, 0.05f) << "prediction on and off gave the same drive: the predictor did not run";
}

// The schedule has what the test claims: lifts, landings and silences of every finger.
TEST(WebLiveAllocation, TheScheduleLiftsLandsAndRestsEveryFinger) {
  for (int f = 0; f < kFingers; ++f) {
    int ups = 0, downs = 0, silent = 0;
    for (std::int64_t k = 0; k < static_cast<std::int64_t>(16 * kEventRateHz); ++k) {
      TouchEvent e;
      if (!event_of(f, k, e)) ++silent;
      else if (e.phase == TouchPhase::up) ++ups;
      else if (e.phase == TouchPhase::down) ++downs;
    }
    EXPECT_GE(ups, 5) << f;
    EXPECT_GE(downs, 5) << f;
    EXPECT_GE(silent, 24 * 7) << f;
  }
}

// The counter counts: a vector made on this thread is seen.
TEST(WebLiveAllocation, TheCounterSeesAnAllocation) {
  const std::uint64_t before = test::allocations_on_this_thread();
  std::vector<int>* v = new std::vector<int>(100);
  const std::uint64_t after = test::allocations_on_this_thread();
  delete v;
  EXPECT_GE(after - before, 2u);
}

}  // namespace
}  // namespace vimg
