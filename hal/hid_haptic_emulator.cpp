#include "hal/hid_haptic_emulator.hpp"

#include <cerrno>

#include "hal/device_error.hpp"

namespace vimg {

using namespace hid_haptics;

class EmulatedHapticDevice final : public HidDevice {
 public:
  explicit EmulatedHapticDevice(HidHapticEmulator& host) : host_(host) {}

  void write(std::span<const std::uint8_t> report) override {
    check();
    if (report.size() != static_cast<std::size_t>(kTriggerReportSize) || report[0] != kTriggerReport) {
      throw DeviceError(host_.path_, "write output report: unknown report", EINVAL);
    }
    HidTrigger trigger;
    trigger.time_us = host_.clock_.now_us();
    const int ordinal = report[1];
    if (ordinal == kOrdinalStop) {
      trigger.waveform = kWaveformStop;
    } else if (ordinal >= kFirstDeviceOrdinal &&
               ordinal - kFirstDeviceOrdinal < static_cast<int>(host_.waveforms_.size())) {
      trigger.waveform = host_.waveforms_[static_cast<std::size_t>(ordinal - kFirstDeviceOrdinal)];
    } else {
      throw DeviceError(host_.path_, "write output report: no waveform ordinal " + std::to_string(ordinal), EINVAL);
    }
    trigger.intensity_percent = report[2];
    trigger.repeat_count = report[3];
    trigger.retrigger_period_ms = report[4] | (report[5] << 8);
    host_.triggers_.push_back(trigger);
  }

  std::size_t get_feature_report(std::span<std::uint8_t> buffer) override {
    check();
    const auto& values = buffer[0] == kWaveformListReport ? host_.waveforms_ : host_.durations_ms_;
    if (buffer[0] != kWaveformListReport && buffer[0] != kDurationListReport) {
      throw DeviceError(host_.path_, "read feature report: unknown report", EINVAL);
    }
    std::size_t length = 1;
    for (const auto value : values) {
      if (length + 2 > buffer.size()) break;
      buffer[length++] = static_cast<std::uint8_t>(value & 0xFF);
      buffer[length++] = static_cast<std::uint8_t>(value >> 8);
    }
    return length;
  }

  void send_feature_report(std::span<const std::uint8_t>) override { check(); }
  const std::string& path() const override { return host_.path_; }

 private:
  void check() {
    if (host_.unplugged_) throw DeviceError(host_.path_, "HID transfer", ENODEV);
  }
  HidHapticEmulator& host_;
};

HidHapticEmulator::HidHapticEmulator(Clock& clock, std::uint16_t vendor_id, std::uint16_t product_id,
                                     std::vector<std::uint16_t> waveforms, std::vector<std::uint16_t> durations_ms)
    : clock_(clock),
      vendor_id_(vendor_id),
      product_id_(product_id),
      waveforms_(std::move(waveforms)),
      durations_ms_(std::move(durations_ms)) {}

std::vector<HidDeviceInfo> HidHapticEmulator::enumerate(std::uint16_t vendor_id, std::uint16_t product_id) {
  if (unplugged_ || (vendor_id != 0 && vendor_id != vendor_id_) || (product_id != 0 && product_id != product_id_)) {
    return {};
  }
  return {HidDeviceInfo{path_, vendor_id_, product_id_, "emulated haptic controller", kUsagePage,
                        kSimpleHapticController}};
}

std::unique_ptr<HidDevice> HidHapticEmulator::open(const std::string& path) {
  if (unplugged_ || path != path_) {
    throw DeviceError(path, "open HID device", ENOENT);
  }
  return std::make_unique<EmulatedHapticDevice>(*this);
}

}  // namespace vimg
