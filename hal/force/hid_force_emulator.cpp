#include "hal/force/hid_force_emulator.hpp"

#include <algorithm>

#include "primitives/force_sum.hpp"

namespace vimg {

int HidForceEmulator::write(std::span<const std::uint8_t> report) {
  if (unplugged_) return -1;
  const auto f = report.size() == hid_force::kForceReportSize ? hid_force::decode_force(report) : std::nullopt;
  if (!f) {
    ++malformed_;
    return static_cast<int>(report.size());
  }
  ++force_reports_;
  received_.push_back(*f);
  since_force_s_ = 0.0;
  enabled_ = f->enable;
  // The firmware never renders above its own limit, whatever the host sends.
  force_N_ = f->enable ? clamp_magnitude(f->force_N, info_.limits.max_force_N) : Vec3{};
  return static_cast<int>(report.size());
}

int HidForceEmulator::read(std::span<std::uint8_t> buffer, int) {
  if (unplugged_) return -1;
  if (queue_.empty()) return 0;
  const auto report = queue_.front();
  queue_.erase(queue_.begin());
  const std::size_t n = std::min(buffer.size(), report.size());
  std::copy_n(report.begin(), n, buffer.begin());
  return static_cast<int>(n);
}

int HidForceEmulator::get_feature_report(std::span<std::uint8_t> buffer) {
  if (unplugged_ || !answers_info_) return -1;
  if (buffer.empty() || buffer[0] != hid_force::kInfoReportId) return -1;
  const auto report = hid_force::encode_info(info_);
  const std::size_t n = std::min(buffer.size(), report.size());
  std::copy_n(report.begin(), n, buffer.begin());
  return static_cast<int>(n);
}

void HidForceEmulator::emit_state() {
  hid_force::StateReport s;
  s.sequence = sequence_++;
  s.buttons = buttons_;
  s.status = static_cast<std::uint8_t>((rendered_force_N() == Vec3{} ? 0 : 1) | (fault_ ? 2 : 0));
  s.position_m = position_m_;
  const auto r = hid_force::encode_state(s);
  queue_.emplace_back(r.begin(), r.end());
}

void HidForceEmulator::advance_s(double dt_s) {
  since_force_s_ += dt_s;
  if (since_force_s_ > hid_force::kWatchdogTimeout_s) {
    force_N_ = {};
    enabled_ = false;
  }
}

void HidForceEmulatorHost::add_force_device(HidCandidate candidate, hid_force::DeviceInfo info) {
  entries_.push_back({std::move(candidate), Kind::force, info});
}

void HidForceEmulatorHost::add_other_device(HidCandidate candidate) { entries_.push_back({std::move(candidate), Kind::other, {}}); }

void HidForceEmulatorHost::add_locked_device(HidCandidate candidate) { entries_.push_back({std::move(candidate), Kind::locked, {}}); }

std::vector<HidCandidate> HidForceEmulatorHost::enumerate() {
  std::vector<HidCandidate> list;
  for (const Entry& e : entries_) list.push_back(e.candidate);
  return list;
}

std::unique_ptr<HidTransport> HidForceEmulatorHost::open(const std::string& path, std::string& error) {
  for (const Entry& e : entries_) {
    if (e.candidate.path != path) continue;
    ++opens_;
    if (e.kind == Kind::locked) {
      error = "cannot open " + path + ": no read/write permission (see the udev rule in docs/volume-force-device.md)";
      return nullptr;
    }
    auto device = std::make_unique<HidForceEmulator>(e.info);
    if (e.kind == Kind::other) device->set_answers_info(false);
    device->emit_state();  // a real device reports at its rate from the start
    return device;
  }
  error = "cannot open " + path + ": No such file or directory";
  return nullptr;
}

}  // namespace vimg
