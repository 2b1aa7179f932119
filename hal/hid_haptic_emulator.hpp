#pragma once
// Test double for HidHost: one emulated Simple Haptic Controller speaking the layout of
// hal/hid_haptics.hpp. Records every trigger with its time; can be unplugged and plugged back.
// It counts the connections (enumerate + open) and the throwing writes apart from the real-time
// ones, so that tests can see which path a driver took.
//
// Threads: one thread at a time uses the device (the driver's DeviceLink decides which);
// set_unplugged() and the counters may be used from any thread.
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "realtime/clock.hpp"
#include "hal/hid_device.hpp"
#include "hal/hid_haptics.hpp"

namespace vimg {

struct HidTrigger {
  std::int64_t time_us = 0;
  std::uint16_t waveform = 0;  // usage, resolved from the ordinal (kWaveformStop for STOP)
  int intensity_percent = 0;
  int repeat_count = 0;
  int retrigger_period_ms = 0;
};

class HidHapticEmulator final : public HidHost {
 public:
  HidHapticEmulator(Clock& clock, std::uint16_t vendor_id, std::uint16_t product_id,
                    std::vector<std::uint16_t> waveforms = {hid_haptics::kWaveformClick, hid_haptics::kWaveformBuzz},
                    std::vector<std::uint16_t> durations_ms = {15, 50});

  std::vector<HidDeviceInfo> enumerate(std::uint16_t vendor_id, std::uint16_t product_id) override;
  std::unique_ptr<HidDevice> open(const std::string& path) override;

  void set_unplugged(bool unplugged);
  const std::vector<HidTrigger>& triggers() const { return triggers_; }
  // Room for `count` more recorded triggers, so that recording allocates nothing meanwhile.
  void reserve_triggers(std::size_t count) { triggers_.reserve(triggers_.size() + count); }
  int opens() const { return opens_.load(std::memory_order_relaxed); }  // open() calls, failed or not
  int throwing_writes() const { return throwing_writes_.load(std::memory_order_relaxed); }
  int completed_try_writes() const { return completed_try_writes_.load(std::memory_order_relaxed); }
  const std::string& path() const { return path_; }

 private:
  friend class EmulatedHapticDevice;
  Clock& clock_;
  std::uint16_t vendor_id_;
  std::uint16_t product_id_;
  std::vector<std::uint16_t> waveforms_;
  std::vector<std::uint16_t> durations_ms_;
  std::string path_ = "/dev/hidraw-emulated";
  std::atomic<bool> unplugged_{false};
  std::atomic<int> plug_count_{0};  // unplugs so far: a handle from before one is dead
  std::vector<HidTrigger> triggers_;
  std::atomic<int> opens_{0};
  std::atomic<int> throwing_writes_{0};
  std::atomic<int> completed_try_writes_{0};
};

}  // namespace vimg
