#include <fcntl.h>
#include <hidapi.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>

#include "hal/device_error.hpp"
#include "hal/hid_device.hpp"

namespace vimg {

namespace {

std::string narrow(const wchar_t* text) {
  std::string out;
  if (text == nullptr) return out;
  for (; *text != L'\0'; ++text) {
    out.push_back(*text < 128 ? static_cast<char>(*text) : '?');
  }
  return out;
}

class HidapiDevice final : public HidDevice {
 public:
  // The real-time writes go straight to the hidraw node with write(2), which is all hid_write does
  // on this backend, except that hid_write formats an error text (malloc) when it fails.
  HidapiDevice(hid_device* handle, std::string path)
      : handle_(handle), path_(std::move(path)), raw_fd_(::open(path_.c_str(), O_WRONLY | O_CLOEXEC)) {}
  ~HidapiDevice() override {
    if (raw_fd_ >= 0) ::close(raw_fd_);
    hid_close(handle_);
  }
  HidapiDevice(const HidapiDevice&) = delete;
  HidapiDevice& operator=(const HidapiDevice&) = delete;

  void write(std::span<const std::uint8_t> report) override {
    errno = 0;
    if (hid_write(handle_, report.data(), report.size()) < 0) fail("write output report");
  }
  int try_write(std::span<const std::uint8_t> report) noexcept override {
    errno = 0;
    const auto written = raw_fd_ >= 0 ? ::write(raw_fd_, report.data(), report.size())
                                      : hid_write(handle_, report.data(), report.size());
    if (written >= 0) return 0;
    return errno != 0 ? errno : EIO;
  }
  std::size_t get_feature_report(std::span<std::uint8_t> buffer) override {
    errno = 0;
    const int got = hid_get_feature_report(handle_, buffer.data(), buffer.size());
    if (got < 0) fail("read feature report " + std::to_string(buffer.empty() ? 0 : buffer[0]));
    return static_cast<std::size_t>(got);
  }
  void send_feature_report(std::span<const std::uint8_t> report) override {
    errno = 0;
    if (hid_send_feature_report(handle_, report.data(), report.size()) < 0) fail("send feature report");
  }
  const std::string& path() const override { return path_; }

 private:
  [[noreturn]] void fail(const std::string& what) {
    const int error_number = errno;
    throw DeviceError(path_, what + " (" + narrow(hid_error(handle_)) + ")", error_number);
  }
  hid_device* handle_;
  std::string path_;
  int raw_fd_ = -1;  // the hidraw node, or -1 when it cannot be opened (then hid_write)
};

}  // namespace

HidapiHost::HidapiHost() {
  if (hid_init() != 0) {
    throw std::runtime_error("hidapi: hid_init failed: " + narrow(hid_error(nullptr)));
  }
}

HidapiHost::~HidapiHost() { hid_exit(); }

std::vector<HidDeviceInfo> HidapiHost::enumerate(std::uint16_t vendor_id, std::uint16_t product_id) {
  std::vector<HidDeviceInfo> devices;
  hid_device_info* list = hid_enumerate(vendor_id, product_id);
  for (const hid_device_info* info = list; info != nullptr; info = info->next) {
    devices.push_back({info->path != nullptr ? info->path : "", info->vendor_id, info->product_id,
                       narrow(info->product_string), info->usage_page, info->usage});
  }
  hid_free_enumeration(list);
  return devices;
}

std::unique_ptr<HidDevice> HidapiHost::open(const std::string& path) {
  errno = 0;
  hid_device* handle = hid_open_path(path.c_str());
  if (handle == nullptr) {
    const int error_number = errno;
    throw DeviceError(path, "open HID device (" + narrow(hid_error(nullptr)) + ")", error_number);
  }
  return std::make_unique<HidapiDevice>(handle, path);
}

}  // namespace vimg
