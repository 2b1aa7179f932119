// The device service: it formats the faults the render thread posts and reconnects a lost device
// off the render thread, with a doubling interval, then hands it back through the DeviceLink. The
// threaded tests run a real render thread and the service thread side by side (TSan checks the
// handover: label "threaded").
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "hal/bos1901_driver.hpp"
#include "hal/bos1901_emulator.hpp"
#include "hal/device_service.hpp"
#include "hal/drv2605l_driver.hpp"
#include "hal/drv2605l_emulator.hpp"
#include "hal/drv2605l_registers.hpp"
#include "hal/emulated_i2c_bus.hpp"
#include "hal/hid_haptic_controller.hpp"
#include "hal/hid_haptic_emulator.hpp"
#include "realtime/clock.hpp"
#include "tests/hal/drv2605l_test_rig.hpp"

namespace vimg {
namespace {

constexpr std::int64_t kMs = 1'000'000;  // ns

// A device whose reconnection fails `failures` times, then succeeds.
class FlakyDevice final : public ServicedDevice {
 public:
  explicit FlakyDevice(int failures) : failures_(failures) {}
  FaultLog& faults() override { return faults_; }
  const DeviceLink& link() const override { return link_; }
  const std::string& device_path() const override { return path_; }
  void reconnect() override {
    attempts_ns.push_back(now_ns);
    if (failures_-- > 0) throw std::runtime_error(path_ + ": open: No such file or directory");
    link_.put_up();
  }
  void lose(int error_number) {  // what the render thread does
    faults_.push({FaultKind::device_gone, error_number, 0});
    link_.take_down();
  }

  std::int64_t now_ns = 0;
  std::vector<std::int64_t> attempts_ns;

 private:
  int failures_;
  FaultLog faults_;
  DeviceLink link_;
  std::string path_ = "/dev/flaky";
};

TEST(DeviceService, ReconnectsAfterOneIntervalThenBacksOffByDoublingUpToTheMaximum) {
  DeviceServiceOptions options;
  options.first_reconnect_interval_s = 0.1;
  options.max_reconnect_interval_s = 0.5;
  DeviceService service(options);
  FlakyDevice device(5);
  service.add(device);
  device.lose(ENODEV);
  for (std::int64_t t = 1000 * kMs; t <= 3000 * kMs; t += kMs) {
    device.now_ns = t;
    service.poll(t);
  }
  // Seen down at 1000 ms; attempts after 100, then 200, 400, 500 (the maximum), 500, ...
  EXPECT_EQ(device.attempts_ns,
            (std::vector<std::int64_t>{1100 * kMs, 1300 * kMs, 1700 * kMs, 2200 * kMs, 2700 * kMs}));
  EXPECT_FALSE(device.link().up());
  device.now_ns = 3200 * kMs;
  service.poll(3200 * kMs);  // the sixth attempt succeeds
  EXPECT_TRUE(device.link().up());
  EXPECT_EQ(service.reconnect_attempts(), 6u);
  // One message per event; the repeated failure reason only once.
  EXPECT_EQ(service.take_messages(),
            (std::vector<std::string>{describe({FaultKind::device_gone, ENODEV, 0}, "/dev/flaky"),
                                      "/dev/flaky: open: No such file or directory; will try to reconnect again",
                                      describe({FaultKind::reconnected, 0, 0}, "/dev/flaky")}));
  EXPECT_TRUE(service.take_messages().empty());
}

TEST(DeviceService, LeavesADeviceWhoseLinkIsUpAlone) {
  DeviceService service;
  FlakyDevice device(0);
  service.add(device);
  for (std::int64_t t = 0; t < 10'000 * kMs; t += 100 * kMs) service.poll(t);
  EXPECT_TRUE(device.attempts_ns.empty());
  EXPECT_TRUE(service.take_messages().empty());
}

TEST(DeviceService, ReportsLostFaultEvents) {
  DeviceService service;
  FlakyDevice device(0);
  service.add(device);
  for (int i = 0; i < 100; ++i) device.faults().push({FaultKind::underrun, 0, i});  // the ring holds 64
  service.poll(0);
  const auto messages = service.take_messages();
  ASSERT_EQ(messages.size(), 65u);
  EXPECT_EQ(messages.back(), "/dev/flaky: 36 fault events lost (the fault log was full)");
}

TEST(DeviceService, KeepsOnlyTheNewestMessagesWhenNobodyTakesThem) {
  DeviceService service;
  FlakyDevice device(0);
  service.add(device);
  const int total = static_cast<int>(DeviceService::kMaxMessages) + 40;
  for (int i = 0; i < total; ++i) {
    device.faults().push({FaultKind::underrun, 0, i});
    service.poll(0);
  }
  const auto messages = service.take_messages();
  ASSERT_EQ(messages.size(), DeviceService::kMaxMessages);
  EXPECT_EQ(messages.back(), describe({FaultKind::underrun, 0, 0}, "/dev/flaky"));
}

// --- The render thread and the service thread together, on the real clock ------------------------

std::vector<float> carrier(double frequency_hz, double duration_s, double amplitude) {
  std::vector<float> samples(static_cast<std::size_t>(std::lround(duration_s * 8000.0)));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i] = static_cast<float>(amplitude *
                                    std::sin(2.0 * std::numbers::pi * frequency_hz * static_cast<double>(i) / 8000.0));
  }
  return samples;
}

// Writes `pattern` over and over in 10 ms blocks at absolute deadlines, like the renderer.
class RenderThread {
 public:
  RenderThread(DriveSink& sink, std::vector<float> pattern) : sink_(sink), pattern_(std::move(pattern)) {
    thread_ = std::thread([this] { run(); });
  }
  ~RenderThread() { stop(); }
  void stop() {
    running_.store(false);
    if (thread_.joinable()) thread_.join();
  }

 private:
  void run() {
    constexpr std::size_t kBlock = 80;
    const std::int64_t start_ns = monotonic_ns();
    for (std::uint64_t k = 0; running_.load(); ++k) {
      sleep_until_ns(start_ns + static_cast<std::int64_t>(k) * 10 * kMs);
      const std::size_t offset = (k * kBlock) % pattern_.size();
      sink_.write(std::span<const float>(pattern_).subspan(offset, kBlock), static_cast<double>(k) * 0.01);
    }
  }

  DriveSink& sink_;
  std::vector<float> pattern_;  // a whole number of blocks
  std::atomic<bool> running_{true};
  std::thread thread_;
};

bool eventually(const std::function<bool()>& condition, double timeout_s = 20.0) {
  const std::int64_t give_up_ns = monotonic_ns() + static_cast<std::int64_t>(timeout_s * 1e9);
  while (!condition()) {
    if (monotonic_ns() > give_up_ns) return false;
    sleep_until_ns(monotonic_ns() + 2 * kMs);
  }
  return true;
}

class Messages {
 public:
  explicit Messages(DeviceService& service) : service_(service) {}
  void collect() {
    for (auto& taken : service_.take_messages()) seen_.push_back(std::move(taken));
  }
  bool has(const std::string& message) {
    collect();
    return std::find(seen_.begin(), seen_.end(), message) != seen_.end();
  }
  // The gone and reconnected messages in order; failed attempts, underruns etc. left out.
  std::vector<std::string> link_events(const std::string& path) const {
    const auto gone = describe({FaultKind::device_gone, ENODEV, 0}, path);
    const auto back = describe({FaultKind::reconnected, 0, 0}, path);
    std::vector<std::string> events;
    for (const auto& message : seen_) {
      if (message == gone || message == back) events.push_back(message);
    }
    return events;
  }

 private:
  DeviceService& service_;
  std::vector<std::string> seen_;
};

DeviceServiceOptions quick_service() {
  DeviceServiceOptions options;
  options.poll_interval_s = 0.005;
  options.first_reconnect_interval_s = 0.02;
  options.max_reconnect_interval_s = 0.1;
  return options;
}

// Unplugs the device while the render thread plays, waits for "device gone", plugs it back, waits
// for "reconnected" and for the render thread's own transfers to flow again.
template <class Device>
void unplug_and_replug(Device& device, Messages& messages, const std::string& path,
                       const std::function<int()>& render_transfers) {
  ASSERT_TRUE(eventually([&] { return render_transfers() > 10; })) << "no output before the unplug";
  device.set_unplugged(true);
  const auto gone = describe({FaultKind::device_gone, ENODEV, 0}, path);
  ASSERT_TRUE(eventually([&] { return messages.has(gone); }));
  device.set_unplugged(false);
  const auto back = describe({FaultKind::reconnected, 0, 0}, path);
  ASSERT_TRUE(eventually([&] { return messages.has(back); }));
  const int after_reconnect = render_transfers();
  EXPECT_TRUE(eventually([&] { return render_transfers() > after_reconnect + 10; })) << "output did not resume";
}

TEST(DeviceServiceThreads, Drv2605lIsReconnectedOffTheRenderThreadAndOutputResumes) {
  SystemClock clock;
  Drv2605lEmulator chip(clock);
  EmulatedI2cBus bus;
  bus.attach(0x5A, chip);
  Drv2605lDriver driver(bus, &chip.enable_pin(), clock, test::lra_profile());
  DeviceService service(quick_service());
  service.add(driver);
  driver.open(8000.0);
  const int resets_at_open = chip.resets();
  Messages messages(service);
  {
    RenderThread render(driver, carrier(175.0, 0.05, 0.6));  // 50 ms of carrier, then again
    service.start();
    unplug_and_replug(bus, messages, bus.path(), [&] { return bus.completed_try_transfers(); });
    render.stop();
    service.stop();
  }
  messages.collect();
  EXPECT_EQ(messages.link_events(bus.path()),
            (std::vector<std::string>{describe({FaultKind::device_gone, ENODEV, 0}, bus.path()),
                                      describe({FaultKind::reconnected, 0, 0}, bus.path())}));
  EXPECT_EQ(bus.reopen_count(), 1);
  EXPECT_EQ(chip.resets(), resets_at_open + 1);  // initialized once more, by the service
  driver.close();
  EXPECT_TRUE(chip.standby());
  EXPECT_TRUE(chip.violations().empty());
}

TEST(DeviceServiceThreads, Bos1901IsReconnectedOffTheRenderThreadAndOutputResumes) {
  SystemClock clock;
  Bos1901Emulator chip(clock);
  ActuatorProfile profile;
  profile.type = ActuatorType::voice_coil;
  profile.rated_voltage_V = 95.0;
  Bos1901Driver driver(chip, clock, profile);
  DeviceService service(quick_service());
  service.add(driver);
  driver.open(8000.0);
  Messages messages(service);
  {
    RenderThread render(driver, carrier(250.0, 0.04, 0.5));
    service.start();
    unplug_and_replug(chip, messages, chip.path(), [&] { return chip.completed_try_transfers(); });
    render.stop();
    service.stop();
  }
  messages.collect();
  EXPECT_EQ(messages.link_events(chip.path()),
            (std::vector<std::string>{describe({FaultKind::device_gone, ENODEV, 0}, chip.path()),
                                      describe({FaultKind::reconnected, 0, 0}, chip.path())}));
  EXPECT_EQ(chip.reopen_count(), 1);
  EXPECT_EQ(chip.resets(), 2);  // open() and the reconnection
  driver.close();
  EXPECT_FALSE(chip.output_enabled());
  EXPECT_EQ(chip.output_value(), 0);
}

TEST(DeviceServiceThreads, HidControllerIsReconnectedOffTheRenderThreadAndOutputResumes) {
  SystemClock clock;
  HidHapticEmulator device(clock, 0x1234, 0x5678);
  HidHapticController controller(device, 0x1234, 0x5678, clock);
  DeviceService service(quick_service());
  service.add(controller);
  controller.open(8000.0);
  std::vector<float> bursts = carrier(175.0, 0.01, 0.7);  // 10 ms on, 40 ms off: a click each time
  bursts.resize(400, 0.0f);
  Messages messages(service);
  {
    RenderThread render(controller, bursts);
    service.start();
    unplug_and_replug(device, messages, device.path(), [&] { return device.completed_try_writes(); });
    render.stop();
    service.stop();
  }
  messages.collect();
  EXPECT_EQ(messages.link_events(device.path()),
            (std::vector<std::string>{describe({FaultKind::device_gone, ENODEV, 0}, device.path()),
                                      describe({FaultKind::reconnected, 0, 0}, device.path())}));
  EXPECT_GE(device.opens(), 2);
  EXPECT_EQ(device.throwing_writes(), 0);
  controller.close();
}

}  // namespace
}  // namespace vimg
