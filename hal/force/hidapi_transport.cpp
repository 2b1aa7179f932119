#include <hidapi.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <algorithm>
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

// A wide hidapi string as UTF-8.
std::string utf8(const wchar_t* text) {
  std::string out;
  for (; text && *text; ++text) {
    const auto c = static_cast<std::uint32_t>(*text);
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x110000) {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

}  // namespace

std::unique_ptr<HidapiTransport> HidapiTransport::open(std::uint16_t vendor_id, std::uint16_t product_id, std::string& error) {
  if (!init_hidapi(error)) return nullptr;
  hid_device* d = hid_open(vendor_id, product_id, nullptr);
  if (!d) {
    error = "hidapi: no device with the given vendor and product id (or no permission: see docs/volume-force-device.md)";
    return nullptr;
  }
  return std::unique_ptr<HidapiTransport>(new HidapiTransport(d));
}

std::unique_ptr<HidapiTransport> HidapiTransport::open_path(const std::string& path, std::string& error) {
  if (!init_hidapi(error)) return nullptr;
  hid_device* d = hid_open_path(path.c_str());
  if (!d) {
    error = "cannot open " + path;
    if (::access(path.c_str(), R_OK | W_OK) != 0) {
      const int e = errno;
      if (e == EACCES || e == EPERM) {
        error += ": no read/write permission (see the udev rule in docs/volume-force-device.md)";
      } else {
        error += std::string(": ") + std::strerror(e);
      }
    }
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

std::vector<HidCandidate> HidapiTransportHost::enumerate() {
  std::vector<HidCandidate> found;
  std::string error;
  if (!init_hidapi(error)) return found;
  hid_device_info* list = hid_enumerate(0, 0);
  for (const hid_device_info* d = list; d; d = d->next) {
    if (!d->path) continue;
    // hidraw lists one entry per top-level usage: each path once.
    if (std::any_of(found.begin(), found.end(), [&](const HidCandidate& c) { return c.path == d->path; })) continue;
    found.push_back({d->path, d->vendor_id, d->product_id, utf8(d->product_string)});
  }
  hid_free_enumeration(list);
  return found;
}

std::unique_ptr<HidTransport> HidapiTransportHost::open(const std::string& path, std::string& error) {
  return HidapiTransport::open_path(path, error);
}

}  // namespace vimg
