#include "hal/force/hid_force_protocol.hpp"

#include <algorithm>
#include <cmath>

namespace vimg::hid_force {
namespace {

void put_u16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v & 0xFF);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
std::uint16_t get_u16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }
void put_i16(std::uint8_t* p, std::int16_t v) { put_u16(p, static_cast<std::uint16_t>(v)); }
std::int16_t get_i16(const std::uint8_t* p) { return static_cast<std::int16_t>(get_u16(p)); }
void put_i32(std::uint8_t* p, std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>((u >> (8 * i)) & 0xFF);
}
std::int32_t get_i32(const std::uint8_t* p) {
  std::uint32_t u = 0;
  for (int i = 0; i < 4; ++i) u |= static_cast<std::uint32_t>(p[i]) << (8 * i);
  return static_cast<std::int32_t>(u);
}
std::uint16_t to_u16(double v) { return static_cast<std::uint16_t>(std::clamp(std::lround(v), 0L, 65535L)); }
std::int16_t to_i16(double v) {
  if (!std::isfinite(v)) return 0;
  return static_cast<std::int16_t>(std::clamp(std::lround(v), -32767L, 32767L));
}
std::int32_t to_i32(double v) {
  if (!std::isfinite(v)) return 0;
  return static_cast<std::int32_t>(std::clamp(std::llround(v), -2147483647LL, 2147483647LL));
}

}  // namespace

std::array<std::uint8_t, kInfoReportSize> encode_info(const DeviceInfo& info) {
  std::array<std::uint8_t, kInfoReportSize> r{};
  r[0] = kInfoReportId;
  r[1] = info.version;
  put_u16(&r[2], to_u16(info.limits.max_force_N * 1e3));
  put_u16(&r[4], to_u16(info.limits.max_stiffness_N_per_m));
  put_u16(&r[6], to_u16(info.limits.workspace_m.x * 1e3));
  put_u16(&r[8], to_u16(info.limits.workspace_m.y * 1e3));
  put_u16(&r[10], to_u16(info.limits.workspace_m.z * 1e3));
  put_u16(&r[12], info.report_rate_hz);
  r[14] = info.button_count;
  const double slew_units = info.limits.max_slew_N_per_ms / kSlewUnit_N_per_ms;
  r[15] = std::isfinite(slew_units) ? static_cast<std::uint8_t>(std::clamp(std::lround(slew_units), 1L, 255L)) : 0;
  return r;
}

std::optional<DeviceInfo> decode_info(std::span<const std::uint8_t> r) {
  if (r.size() < kInfoReportSize || r[0] != kInfoReportId) return std::nullopt;
  DeviceInfo info;
  info.version = r[1];
  info.limits.max_force_N = get_u16(&r[2]) * 1e-3;
  info.limits.max_stiffness_N_per_m = get_u16(&r[4]);
  info.limits.workspace_m = Vec3{double(get_u16(&r[6])), double(get_u16(&r[8])), double(get_u16(&r[10]))} * 1e-3;
  info.report_rate_hz = get_u16(&r[12]);
  info.button_count = r[14];
  info.limits.max_slew_N_per_ms = r[15] == 0 ? kDefaultMaxSlew_N_per_ms : r[15] * kSlewUnit_N_per_ms;
  return info;
}

std::array<std::uint8_t, kStateReportSize> encode_state(const StateReport& s) {
  std::array<std::uint8_t, kStateReportSize> r{};
  r[0] = kStateReportId;
  r[1] = s.sequence;
  r[2] = s.buttons;
  r[3] = s.status;
  put_i32(&r[4], to_i32(s.position_m.x * 1e6));
  put_i32(&r[8], to_i32(s.position_m.y * 1e6));
  put_i32(&r[12], to_i32(s.position_m.z * 1e6));
  return r;
}

std::optional<StateReport> decode_state(std::span<const std::uint8_t> r) {
  if (r.size() < kStateReportSize || r[0] != kStateReportId) return std::nullopt;
  StateReport s;
  s.sequence = r[1];
  s.buttons = r[2];
  s.status = r[3];
  s.position_m = Vec3{double(get_i32(&r[4])), double(get_i32(&r[8])), double(get_i32(&r[12]))} * 1e-6;
  return s;
}

std::array<std::uint8_t, kForceReportSize> encode_force(const ForceReport& f) {
  std::array<std::uint8_t, kForceReportSize> r{};
  r[0] = kForceReportId;
  r[1] = f.sequence;
  r[2] = f.enable ? 1 : 0;
  put_i16(&r[3], to_i16(f.force_N.x * 1e3));
  put_i16(&r[5], to_i16(f.force_N.y * 1e3));
  put_i16(&r[7], to_i16(f.force_N.z * 1e3));
  return r;
}

std::optional<ForceReport> decode_force(std::span<const std::uint8_t> r) {
  if (r.size() < kForceReportSize || r[0] != kForceReportId) return std::nullopt;
  ForceReport f;
  f.sequence = r[1];
  f.enable = (r[2] & 1) != 0;
  f.force_N = Vec3{double(get_i16(&r[3])), double(get_i16(&r[5])), double(get_i16(&r[7]))} * 1e-3;
  return f;
}

}  // namespace vimg::hid_force
