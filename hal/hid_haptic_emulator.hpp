#pragma once
// Test double for HidHost: one emulated Simple Haptic Controller speaking the layout of
// hal/hid_haptics.hpp. Records every trigger with its time; can be unplugged and plugged back.
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

  void set_unplugged(bool unplugged) { unplugged_ = unplugged; }
  const std::vector<HidTrigger>& triggers() const { return triggers_; }
  const std::string& path() const { return path_; }

 private:
  friend class EmulatedHapticDevice;
  Clock& clock_;
  std::uint16_t vendor_id_;
  std::uint16_t product_id_;
  std::vector<std::uint16_t> waveforms_;
  std::vector<std::uint16_t> durations_ms_;
  std::string path_ = "/dev/hidraw-emulated";
  bool unplugged_ = false;
  std::vector<HidTrigger> triggers_;
};

}  // namespace vimg
