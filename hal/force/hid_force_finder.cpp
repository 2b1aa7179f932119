#include "hal/force/hid_force_finder.hpp"

#include <cstdio>

#include "realtime/clock.hpp"

namespace vimg {
namespace {

constexpr const char* kUdevHint = "see the udev rule in docs/volume-force-device.md, \"Access to /dev/hidraw\"";

std::string ids(const HidCandidate& c) {
  char text[16];
  std::snprintf(text, sizeof text, "%04x:%04x", c.vendor_id, c.product_id);
  return text;
}

std::string describe(const HidCandidate& c) {
  std::string text = c.vendor_id || c.product_id ? ids(c) + " " + c.path : c.path;
  if (!c.product.empty()) text += " \"" + c.product + "\"";
  return text;
}

// HidForceDevice::open's messages start with "HID force device: "; the list says that already.
std::string reason(std::string error) {
  const std::string prefix = "HID force device: ";
  if (error.rfind(prefix, 0) == 0) error.erase(0, prefix.size());
  return error;
}

}  // namespace

HidForceSearch find_hid_force_device(HidTransportHost& host, const std::string& path, double time_budget_s) {
  HidForceSearch search;
  std::vector<HidCandidate> candidates;
  if (!path.empty()) {
    // The named device only; its ids and product string if the host lists it.
    HidCandidate named{path, 0, 0, ""};
    for (const HidCandidate& c : host.enumerate()) {
      if (c.path == path) named = c;
    }
    candidates.push_back(named);
  } else {
    candidates = host.enumerate();
    if (candidates.empty()) {
      search.report = std::string("no HID device is visible (none is plugged in, or this user may not read /dev/hidraw*: ") +
                      kUdevHint + ")";
      return search;
    }
  }
  const double start_s = monotonic_s();
  std::string lines;
  for (const HidCandidate& candidate : candidates) {
    std::string why;
    if (monotonic_s() - start_s > time_budget_s) {
      why = "not tried: the search ran out of time";
    } else {
      std::string error;
      auto transport = host.open(candidate.path, error);
      if (!transport) {
        why = error;
      } else if (auto device = HidForceDevice::open(std::move(transport), error)) {
        search.device = std::move(device);
        search.opened = candidate;
        search.report.clear();
        return search;
      } else {
        why = reason(error);
      }
    }
    lines += "\n  " + describe(candidate) + ": " + why;
  }
  search.report = (path.empty() ? std::string("no HID device answers the force protocol (info feature report 0x01, version 1); found:")
                                : std::string("the device does not answer the force protocol (info feature report 0x01, version 1):")) +
                  lines;
  return search;
}

}  // namespace vimg
