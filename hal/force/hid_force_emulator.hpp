#pragma once
// An emulated do-it-yourself force device speaking the open HID force protocol, as a
// HidTransport: tests drive the probe position and the device clock, and check what force the
// device would render, including the 50 ms watchdog and the enable flag.
#include <vector>

#include "hal/force/hid_force_protocol.hpp"
#include "hal/force/hid_transport.hpp"

namespace vimg {

class HidForceEmulator final : public HidTransport {
 public:
  explicit HidForceEmulator(hid_force::DeviceInfo info = {}) : info_(info) {}

  // HidTransport
  int write(std::span<const std::uint8_t> report) override;
  int read(std::span<std::uint8_t> buffer, int timeout_ms) override;
  int get_feature_report(std::span<std::uint8_t> buffer) override;

  // The device side.
  void set_position(const Vec3& position_m) { position_m_ = position_m; }
  void set_buttons(std::uint8_t buttons) { buttons_ = buttons; }
  void set_fault(bool fault) { fault_ = fault; }
  // Queues one state report (a real device sends them at its report rate).
  void emit_state();
  // Advances the device clock; the watchdog zeroes the force after 50 ms without a force report.
  void advance_s(double dt_s);
  // What the motors render now.
  Vec3 rendered_force_N() const { return enabled_ && !fault_ ? force_N_ : Vec3{}; }
  bool enabled() const { return enabled_; }
  int force_reports() const { return force_reports_; }
  int malformed_reports() const { return malformed_; }
  const std::vector<hid_force::ForceReport>& received() const { return received_; }
  // Test hook: the next transport call fails as if the device were unplugged.
  void unplug() { unplugged_ = true; }

 private:
  hid_force::DeviceInfo info_;
  Vec3 position_m_;
  std::uint8_t buttons_ = 0;
  bool fault_ = false;
  std::uint8_t sequence_ = 0;
  std::vector<std::vector<std::uint8_t>> queue_;
  Vec3 force_N_;
  bool enabled_ = false;
  double since_force_s_ = 0.0;
  int force_reports_ = 0;
  int malformed_ = 0;
  std::vector<hid_force::ForceReport> received_;
  bool unplugged_ = false;
};

}  // namespace vimg
