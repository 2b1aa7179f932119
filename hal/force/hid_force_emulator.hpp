#pragma once
// An emulated do-it-yourself force device speaking the open HID force protocol, as a
// HidTransport: tests drive the probe position and the device clock, and check what force the
// device would render, including the 50 ms watchdog and the enable flag.
#include <memory>
#include <string>
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
  // Test hook: a HID device of another kind (a keyboard, a mouse) answers no info report 0x01.
  void set_answers_info(bool answers) { answers_info_ = answers; }

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
  bool answers_info_ = true;
};

// A host with emulated HID devices, for the device search (find_hid_force_device): force devices
// (a HidForceEmulator each time one is opened), devices of other kinds, and devices this user may
// not open.
class HidForceEmulatorHost final : public HidTransportHost {
 public:
  void add_force_device(HidCandidate candidate, hid_force::DeviceInfo info = {});
  void add_other_device(HidCandidate candidate);
  void add_locked_device(HidCandidate candidate);

  std::vector<HidCandidate> enumerate() override;
  std::unique_ptr<HidTransport> open(const std::string& path, std::string& error) override;
  int opens() const { return opens_; }

 private:
  enum class Kind { force, other, locked };
  struct Entry {
    HidCandidate candidate;
    Kind kind;
    hid_force::DeviceInfo info;
  };
  std::vector<Entry> entries_;
  int opens_ = 0;
};

}  // namespace vimg
