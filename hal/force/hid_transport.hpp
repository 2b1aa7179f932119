#pragma once
// The few hidapi calls the HID force device needs, behind an interface: hidapi in production,
// an emulated device in tests. Byte 0 of every buffer is the report id.
//
// Threads: a transport belongs to one thread at a time; HidForceDevice calls read() and write()
// from the haptic loop's thread, so an implementation must not lock or throw there (hidapi's own
// error path may allocate its error text; the loop reads no text from it).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace vimg {

class HidTransport {
 public:
  virtual ~HidTransport() = default;
  // Returns the bytes written, or -1 on error.
  virtual int write(std::span<const std::uint8_t> report) = 0;
  // Waits up to timeout_ms (0: do not wait) for an input report. Returns its size, 0 on timeout,
  // -1 on error.
  virtual int read(std::span<std::uint8_t> buffer, int timeout_ms) = 0;
  // buffer[0] holds the requested report id. Returns the size read, or -1 on error.
  virtual int get_feature_report(std::span<std::uint8_t> buffer) = 0;
};

// A HID device the host can see.
struct HidCandidate {
  std::string path;  // e.g. /dev/hidraw3
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::string product;  // the product string, UTF-8 ("" when the device gives none)
};

// Finding and opening HID devices: hidapi in production (HidapiTransportHost), an emulated set
// of devices in tests (HidForceEmulatorHost). Control thread only (allocates).
class HidTransportHost {
 public:
  virtual ~HidTransportHost() = default;
  // Every visible HID device, each path once.
  virtual std::vector<HidCandidate> enumerate() = 0;
  // Null with a reason when the device cannot be opened.
  virtual std::unique_ptr<HidTransport> open(const std::string& path, std::string& error) = 0;
};

// hidapi (hidraw backend). Opens the first device with the ids, or a given hidraw path.
class HidapiTransport final : public HidTransport {
 public:
  static std::unique_ptr<HidapiTransport> open(std::uint16_t vendor_id, std::uint16_t product_id, std::string& error);
  static std::unique_ptr<HidapiTransport> open_path(const std::string& path, std::string& error);
  ~HidapiTransport() override;
  int write(std::span<const std::uint8_t> report) override;
  int read(std::span<std::uint8_t> buffer, int timeout_ms) override;
  int get_feature_report(std::span<std::uint8_t> buffer) override;

 private:
  explicit HidapiTransport(void* device) : device_(device) {}
  void* device_;  // hid_device*
};

}  // namespace vimg

namespace vimg {

// hid_enumerate(0, 0) and hid_open_path.
class HidapiTransportHost final : public HidTransportHost {
 public:
  std::vector<HidCandidate> enumerate() override;
  std::unique_ptr<HidTransport> open(const std::string& path, std::string& error) override;
};

}  // namespace vimg
