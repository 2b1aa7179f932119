#pragma once
// USB HID devices. Real: HidapiHost (hidapi 0.13, hidraw backend). Test double: HidHapticEmulator.
// Threads: one thread at a time uses a device (its driver's DeviceLink decides which); write() and
// the reports throw with a message (control and service threads), try_write() is for the
// real-time thread: it returns 0 or the errno value and never throws or allocates.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace vimg {

struct HidDeviceInfo {
  std::string path;
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::string product;
  std::uint16_t usage_page = 0;
  std::uint16_t usage = 0;
};

class HidDevice {
 public:
  virtual ~HidDevice() = default;
  // Output report; byte 0 is the report id. Throws DeviceError.
  virtual void write(std::span<const std::uint8_t> report) = 0;
  // The same for the real-time thread: 0, or the errno value (EIO when the backend gives none).
  virtual int try_write(std::span<const std::uint8_t> report) noexcept = 0;
  // Feature report; set buffer[0] to the report id. Returns the bytes read (id included).
  virtual std::size_t get_feature_report(std::span<std::uint8_t> buffer) = 0;
  virtual void send_feature_report(std::span<const std::uint8_t> report) = 0;
  virtual const std::string& path() const = 0;
};

class HidHost {
 public:
  virtual ~HidHost() = default;
  // vendor_id / product_id 0 match any.
  virtual std::vector<HidDeviceInfo> enumerate(std::uint16_t vendor_id, std::uint16_t product_id) = 0;
  virtual std::unique_ptr<HidDevice> open(const std::string& path) = 0;  // throws DeviceError
};

// hid_init / hid_enumerate / hid_open_path / hid_write / hid_get_feature_report.
class HidapiHost final : public HidHost {
 public:
  HidapiHost();   // throws std::runtime_error when hid_init fails
  ~HidapiHost() override;
  HidapiHost(const HidapiHost&) = delete;
  HidapiHost& operator=(const HidapiHost&) = delete;

  std::vector<HidDeviceInfo> enumerate(std::uint16_t vendor_id, std::uint16_t product_id) override;
  std::unique_ptr<HidDevice> open(const std::string& path) override;
};

}  // namespace vimg
