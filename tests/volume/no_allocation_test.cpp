// What runs on the haptic loop's thread never allocates: the HID force device's read and write,
// the safety stack, and a whole cycle (read, render, safety stack, write) with the simulated
// device. The global operator new is replaced for this test program and counts the allocations
// made on the current thread while armed.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <new>

#include "hal/force/hid_force_device.hpp"
#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/safe_haptic_cycle.hpp"
#include "tests/volume/test_shaders.hpp"

namespace {
thread_local bool g_armed = false;
thread_local int g_allocations = 0;

void* counted_allocation(std::size_t n) {
  if (g_armed) ++g_allocations;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return counted_allocation(n); }
void* operator new[](std::size_t n) { return counted_allocation(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace vimg {
namespace {

// Counts the allocations made on this thread while it lives.
class AllocationCounter {
 public:
  AllocationCounter() {
    g_allocations = 0;
    g_armed = true;
  }
  ~AllocationCounter() { g_armed = false; }
  int count() const { return g_allocations; }
};

// A device side that allocates nothing itself: state reports from a fixed ring of reports.
class FixedTransport final : public HidTransport {
 public:
  int write(std::span<const std::uint8_t> report) override {
    ++writes;
    return fail ? -1 : static_cast<int>(report.size());
  }
  int read(std::span<std::uint8_t> buffer, int) override {
    if (fail) return -1;
    if (pending == 0) return 0;
    --pending;
    const auto r = hid_force::encode_state({sequence++, 0, 1, Vec3{0.001 * sequence, 0.0, 0.0}});
    std::copy_n(r.begin(), std::min(buffer.size(), r.size()), buffer.begin());
    return static_cast<int>(r.size());
  }
  int get_feature_report(std::span<std::uint8_t> buffer) override {
    const auto r = hid_force::encode_info({});
    std::copy_n(r.begin(), std::min(buffer.size(), r.size()), buffer.begin());
    return static_cast<int>(r.size());
  }
  int pending = 1;
  std::uint8_t sequence = 0;
  int writes = 0;
  bool fail = false;
};

TEST(NoAllocation, HidForceDeviceReadAndWriteIncludingErrors) {
  auto transport = std::make_unique<FixedTransport>();
  FixedTransport& side = *transport;
  std::string error;
  auto device = HidForceDevice::open(std::move(transport), error);
  ASSERT_TRUE(device) << error;
  ProbeSample s;
  AllocationCounter counter;
  for (int i = 0; i < 1000; ++i) {
    side.pending = i == 0 ? 1 : i % 3;  // sometimes none, sometimes several reports waiting
    ASSERT_TRUE(device->read(i * 1e-3, s));
    ASSERT_TRUE(device->write_force({0.1, 0.0, 0.0}));
  }
  side.fail = true;
  EXPECT_FALSE(device->read(1.0, s));
  EXPECT_FALSE(device->write_force({}));
  EXPECT_EQ(device->last_fault(), PortFault::io_error);
  EXPECT_EQ(counter.count(), 0);
}

TEST(NoAllocation, AWholeCycleWithTheSimulatedDeviceAndEveryLayerActing) {
  std::vector<HandPathPoint> path;
  for (int i = 0; i <= 20; ++i) path.push_back({0.05 * i, Vec3{0.09 * std::sin(0.5 * i), 0.0, 0.0}});
  SimulatedForceDevice sim(path);
  HapticScene scene(DeviceProfile{}, {},
                    {std::make_shared<testing::AnchorSpringShader>(Vec3{}, 2000.0),
                     std::make_shared<testing::VibrationShader>(Vec3{0.0, 1.0, 0.0}, 200.0)},
                    {});
  SafetySettings settings;
  settings.stale_limit_cycles = 50;
  SafeHapticCycle cycle(sim.limits(), settings, {0.1}, 1e-3);
  cycle.render().set_scene(&scene, 0.0);
  std::uint32_t flags_seen = 0;
  AllocationCounter counter;
  for (int n = 0; n < 1000; ++n) {
    sim.freeze_measurements(n >= 900);  // the stale watchdog trips at the end
    const ForceCycleRecord r = cycle.step(sim, n * 1e-3, false);
    flags_seen |= r.flags;
    if (r.fault != ForceFault::none) break;
  }
  cycle.stop(sim, 1.0);
  EXPECT_EQ(counter.count(), 0);
  for (std::uint32_t flag : {safety_flag::gate, safety_flag::wall, safety_flag::clamp, safety_flag::slew, safety_flag::stale}) {
    EXPECT_TRUE(flags_seen & flag) << safety_flag_names(flag);
  }
}

TEST(NoAllocation, TheCounterSeesAnAllocation) {
  AllocationCounter counter;
  auto p = std::make_unique<int>(3);
  EXPECT_EQ(counter.count(), 1);
}

}  // namespace
}  // namespace vimg
