#include <hidapi.h>

#include <mutex>

#include "hal/force/hid_transport.hpp"

namespace vimg {
namespace {

bool init_hidapi(std::string& error) {
  static std::once_flag once;
  static int status = 0;
  std::call_once(once, [] { status = hid_init(); });
  if (status != 0) error = "hidapi: cannot initialise";
  return status == 0;
}

hid_device* dev(void* p) { return static_cast<hid_device*>(p); }

}  // namespace

std::unique_ptr<HidapiTransport> HidapiTransport::open(std::uint16_t vendor_id, std::uint16_t product_id, std::string& error) {
  if (!init_hidapi(error)) return nullptr;
  hid_device* d = hid_open(vendor_id, product_id, nullptr);
  if (!d) {
    error = "hidapi: no device with the given vendor and product id (or no permission: see docs/volume.md)";
    return nullptr;
  }
  return std::unique_ptr<HidapiTransport>(new HidapiTransport(d));
}

std::unique_ptr<HidapiTransport> HidapiTransport::open_path(const std::string& path, std::string& error) {
  if (!init_hidapi(error)) return nullptr;
  hid_device* d = hid_open_path(path.c_str());
  if (!d) {
    error = "hidapi: cannot open " + path;
    return nullptr;
  }
  return std::unique_ptr<HidapiTransport>(new HidapiTransport(d));
}

HidapiTransport::~HidapiTransport() { hid_close(dev(device_)); }

int HidapiTransport::write(std::span<const std::uint8_t> report) { return hid_write(dev(device_), report.data(), report.size()); }

int HidapiTransport::read(std::span<std::uint8_t> buffer, int timeout_ms) {
  return hid_read_timeout(dev(device_), buffer.data(), buffer.size(), timeout_ms);
}

int HidapiTransport::get_feature_report(std::span<std::uint8_t> buffer) {
  return hid_get_feature_report(dev(device_), buffer.data(), buffer.size());
}

}  // namespace vimg
