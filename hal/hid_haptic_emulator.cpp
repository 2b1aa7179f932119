#include "hal/hid_haptic_emulator.hpp"

#include <cerrno>

#include "hal/device_error.hpp"

namespace vimg {

using namespace hid_haptics;

// A handle from open(): like a hidraw descriptor it stays dead once its device was unplugged, even
// after the device is back.
class EmulatedHapticDevice final : public HidDevice {
 public:
  explicit EmulatedHapticDevice(HidHapticEmulator& host)
      : host_(host), plug_count_(host.plug_count_.load(std::memory_order_relaxed)) {}

  void write(std::span<const std::uint8_t> report) override {
    host_.throwing_writes_.fetch_add(1, std::memory_order_relaxed);
    if (const int error = record(report)) {
      throw DeviceError(host_.path_, "write output report", error);
    }
  }

  int try_write(std::span<const std::uint8_t> report) noexcept override {
    const int error = record(report);
    if (error == 0) host_.completed_try_writes_.fetch_add(1, std::memory_order_relaxed);
    return error;
  }

  std::size_t get_feature_report(std::span<std::uint8_t> buffer) override {
    if (const int error = state()) throw DeviceError(host_.path_, "read feature report", error);
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

  void send_feature_report(std::span<const std::uint8_t>) override {
    if (const int error = state()) throw DeviceError(host_.path_, "send feature report", error);
  }
  const std::string& path() const override { return host_.path_; }

 private:
  int state() const noexcept {
    const bool gone = host_.unplugged_.load(std::memory_order_relaxed) ||
                      host_.plug_count_.load(std::memory_order_relaxed) != plug_count_;
    return gone ? ENODEV : 0;
  }

  // 0 and the trigger recorded, or the errno value.
  int record(std::span<const std::uint8_t> report) noexcept {
    if (const int error = state()) return error;
    if (report.size() != static_cast<std::size_t>(kTriggerReportSize) || report[0] != kTriggerReport) {
      return EINVAL;
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
      return EINVAL;  // no such waveform ordinal
    }
    trigger.intensity_percent = report[2];
    trigger.repeat_count = report[3];
    trigger.retrigger_period_ms = report[4] | (report[5] << 8);
    host_.triggers_.push_back(trigger);
    return 0;
  }

  HidHapticEmulator& host_;
  int plug_count_;
};

HidHapticEmulator::HidHapticEmulator(Clock& clock, std::uint16_t vendor_id, std::uint16_t product_id,
                                     std::vector<std::uint16_t> waveforms, std::vector<std::uint16_t> durations_ms)
    : clock_(clock),
      vendor_id_(vendor_id),
      product_id_(product_id),
      waveforms_(std::move(waveforms)),
      durations_ms_(std::move(durations_ms)) {}

void HidHapticEmulator::set_unplugged(bool unplugged) {
  if (unplugged && !unplugged_.exchange(true, std::memory_order_relaxed)) {
    plug_count_.fetch_add(1, std::memory_order_relaxed);  // handles opened before stay dead
  } else if (!unplugged) {
    unplugged_.store(false, std::memory_order_relaxed);
  }
}

std::vector<HidDeviceInfo> HidHapticEmulator::enumerate(std::uint16_t vendor_id, std::uint16_t product_id) {
  if (unplugged_.load(std::memory_order_relaxed) || (vendor_id != 0 && vendor_id != vendor_id_) ||
      (product_id != 0 && product_id != product_id_)) {
    return {};
  }
  return {HidDeviceInfo{path_, vendor_id_, product_id_, "emulated haptic controller", kUsagePage,
                        kSimpleHapticController}};
}

std::unique_ptr<HidDevice> HidHapticEmulator::open(const std::string& path) {
  opens_.fetch_add(1, std::memory_order_relaxed);
  if (unplugged_.load(std::memory_order_relaxed) || path != path_) {
    throw DeviceError(path, "open HID device", ENOENT);
  }
  return std::make_unique<EmulatedHapticDevice>(*this);
}

}  // namespace vimg
