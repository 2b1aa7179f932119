#pragma once
// A force device speaking the open HID force protocol (hid_force_protocol.hpp) over a
// HidTransport. Velocity is estimated from successive positions with a first-order low-pass
// (cut-off velocity_cutoff_hz). ProbeSample::sequence counts the state reports by their own
// sequence byte (unwrapped), so a device that stops reporting leaves it unchanged. Closing sends a
// zero force with enable cleared.
//
// Threads: open() and the destructor on a control thread (open allocates and formats messages);
// read(), write_force() and last_fault() on the loop thread: they neither allocate nor throw, and
// report errors as a PortFault code, which the control thread turns into text.
#include <memory>
#include <string>

#include "hal/force/force_device.hpp"
#include "hal/force/hid_force_protocol.hpp"
#include "hal/force/hid_transport.hpp"

namespace vimg {

class HidForceDevice final : public ForceDevice {
 public:
  // Reads the device info; null with a message if the device does not speak protocol 1.
  static std::unique_ptr<HidForceDevice> open(std::unique_ptr<HidTransport> transport, std::string& error,
                                              double velocity_cutoff_hz = 50.0);
  ~HidForceDevice() override;

  bool read(double time_s, ProbeSample& sample) override;
  bool write_force(const Vec3& force_N) override;
  ForceDeviceLimits limits() const override { return info_.limits; }
  PortFault last_fault() const noexcept override { return fault_; }
  const hid_force::DeviceInfo& info() const { return info_; }
  // Disables the force output (zero force, enable clear) until the next write_force.
  bool disable();

 private:
  HidForceDevice(std::unique_ptr<HidTransport> transport, hid_force::DeviceInfo info, double cutoff_hz)
      : transport_(std::move(transport)), info_(info), cutoff_hz_(cutoff_hz) {}
  bool send(const Vec3& force_N, bool enable);

  std::unique_ptr<HidTransport> transport_;
  hid_force::DeviceInfo info_;
  double cutoff_hz_;
  bool have_state_ = false;
  hid_force::StateReport state_;
  Vec3 velocity_m_per_s_;
  Vec3 last_position_m_;
  double last_time_s_ = 0.0;
  std::uint8_t sequence_ = 0;
  std::uint64_t measurements_ = 0;
  PortFault fault_ = PortFault::none;
};

}  // namespace vimg
