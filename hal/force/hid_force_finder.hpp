#pragma once
// Finding a force device that speaks the open HID force protocol (hid_force_protocol.hpp):
//   - with a path, that device only;
//   - without, every visible HID device in turn until one answers the info feature report 0x01
//     with protocol version 1.
// When none answers, `report` says what was found and why each did not answer (vendor:product,
// path, product string, reason), or that no HID device is visible at all, pointing to the udev
// rule in docs/volume-force-device.md. The search stops trying new devices once time_budget_s has passed
// (each try is one open and one feature report), so the answer comes within a few seconds.
//
// Threads: a control thread (allocates, may block on the devices).
#include <memory>
#include <string>

#include "hal/force/hid_force_device.hpp"
#include "hal/force/hid_transport.hpp"

namespace vimg {

struct HidForceSearch {
  std::unique_ptr<HidForceDevice> device;  // null when none answered
  HidCandidate opened;                     // the device opened
  std::string report;                      // when none answered: what was found, and why not
};

HidForceSearch find_hid_force_device(HidTransportHost& host, const std::string& path, double time_budget_s = 4.0);

}  // namespace vimg
