#include "hal/force/hid_force_device.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "primitives/force_sum.hpp"

namespace vimg {

std::unique_ptr<HidForceDevice> HidForceDevice::open(std::unique_ptr<HidTransport> transport, std::string& error,
                                                     double velocity_cutoff_hz) {
  if (!transport) {
    error = "no HID transport";
    return nullptr;
  }
  std::array<std::uint8_t, hid_force::kInfoReportSize> buffer{};
  buffer[0] = hid_force::kInfoReportId;
  const int n = transport->get_feature_report(buffer);
  if (n < static_cast<int>(hid_force::kInfoReportSize)) {
    error = "HID force device: cannot read the device info report (0x01)";
    return nullptr;
  }
  const auto info = hid_force::decode_info(buffer);
  if (!info || info->version != hid_force::kProtocolVersion) {
    error = "HID force device: unsupported protocol version " + std::to_string(info ? info->version : 0) + " (expected 1)";
    return nullptr;
  }
  if (!(info->limits.max_force_N > 0.0)) {
    error = "HID force device: the device reports a zero force limit";
    return nullptr;
  }
  return std::unique_ptr<HidForceDevice>(new HidForceDevice(std::move(transport), *info, velocity_cutoff_hz));
}

HidForceDevice::~HidForceDevice() { disable(); }

bool HidForceDevice::read(double time_s, ProbeSample& sample) {
  std::array<std::uint8_t, 64> buffer{};
  bool got = false;
  // Take every queued report and keep the newest; wait a little only if none has ever come.
  for (int i = 0; i < 64; ++i) {
    const int n = transport_->read(buffer, (!have_state_ && !got) ? 20 : 0);
    if (n < 0) {
      fault_ = PortFault::io_error;
      return false;
    }
    if (n == 0) break;
    if (const auto s = hid_force::decode_state(std::span<const std::uint8_t>(buffer.data(), static_cast<std::size_t>(n)))) {
      // The device's sequence byte, unwrapped: a repeated report is no new measurement.
      measurements_ += (have_state_ || got) ? static_cast<std::uint8_t>(s->sequence - state_.sequence) : 1u;
      state_ = *s;
      got = true;
    }
  }
  if (!got && !have_state_) {
    fault_ = PortFault::no_data;
    return false;
  }
  if ((state_.status & 2) != 0) {
    fault_ = PortFault::device_fault;
    return false;
  }
  if (got) {
    if (have_state_ && time_s > last_time_s_) {
      const double dt = time_s - last_time_s_;
      const Vec3 raw = (state_.position_m - last_position_m_) / dt;
      const double alpha = 1.0 - std::exp(-2.0 * std::numbers::pi * cutoff_hz_ * dt);
      velocity_m_per_s_ += alpha * (raw - velocity_m_per_s_);
    }
    have_state_ = true;
    last_position_m_ = state_.position_m;
    last_time_s_ = time_s;
  }
  sample.position_m = state_.position_m;
  sample.velocity_m_per_s = velocity_m_per_s_;
  sample.buttons = state_.buttons;
  sample.sequence = measurements_;
  return true;
}

bool HidForceDevice::send(const Vec3& force_N, bool enable) {
  const auto report = hid_force::encode_force({sequence_++, enable, clamp_magnitude(force_N, info_.limits.max_force_N)});
  if (transport_->write(report) == static_cast<int>(report.size())) return true;
  fault_ = PortFault::io_error;
  return false;
}

bool HidForceDevice::write_force(const Vec3& force_N) { return send(force_N, true); }

bool HidForceDevice::disable() { return send({}, false); }

}  // namespace vimg
