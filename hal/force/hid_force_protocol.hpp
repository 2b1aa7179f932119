#pragma once
// The open HID report protocol for do-it-yourself force devices (docs/volume-force-device.md, "HID force
// protocol"). All multi-byte fields are little-endian; byte 0 of every report is its report id.
//
//   Feature report 0x01, device info (16 bytes, device -> host, read once at open):
//     [1] protocol version (1)  [2..3] Fmax, mN (u16)  [4..5] Kmax, N/m (u16)
//     [6..7] [8..9] [10..11] workspace x, y, z, mm (u16)  [12..13] state report rate, Hz (u16)
//     [14] number of buttons  [15] slew limit, 0.1 N/ms units (u8): the largest force change the
//     device accepts per millisecond; 0 means the default, kDefaultMaxSlew_N_per_ms (1 N/ms).
//     Byte 15 was "reserved, 0" before it carried the slew limit, so older devices decode to the
//     default. encode_info rounds to the nearest 0.1 N/ms within 0.1 .. 25.5 N/ms.
//   Input report 0x02, state (16 bytes, device -> host, at the report rate, 1 kHz nominal):
//     [1] sequence (u8, wraps)  [2] buttons (bit i = button i)  [3] status (bit 0 force enabled,
//     bit 1 fault)  [4..7] [8..11] [12..15] position x, y, z, micrometres (i32)
//   Output report 0x03, force (9 bytes, host -> device, once per haptic cycle):
//     [1] sequence (u8)  [2] flags (bit 0 enable)  [3..4] [5..6] [7..8] force x, y, z, mN (i16)
//
// The device renders the force while enable is set and zeroes it when enable is clear, when a
// fault occurs, or when no force report has arrived for 50 ms (the watchdog).
#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "hal/force/force_device.hpp"

namespace vimg::hid_force {

inline constexpr std::uint8_t kInfoReportId = 0x01;
inline constexpr std::uint8_t kStateReportId = 0x02;
inline constexpr std::uint8_t kForceReportId = 0x03;
inline constexpr std::uint8_t kProtocolVersion = 1;
inline constexpr std::size_t kInfoReportSize = 16;
inline constexpr std::size_t kStateReportSize = 16;
inline constexpr std::size_t kForceReportSize = 9;
inline constexpr double kWatchdogTimeout_s = 0.05;
inline constexpr double kSlewUnit_N_per_ms = 0.1;  // info report byte 15

struct DeviceInfo {
  std::uint8_t version = kProtocolVersion;
  ForceDeviceLimits limits;
  std::uint16_t report_rate_hz = 1000;
  std::uint8_t button_count = 2;
};

struct StateReport {
  std::uint8_t sequence = 0;
  std::uint8_t buttons = 0;
  std::uint8_t status = 0;
  Vec3 position_m;  // sent in micrometres
};

struct ForceReport {
  std::uint8_t sequence = 0;
  bool enable = false;
  Vec3 force_N;  // sent in millinewtons, saturated to +-32.767 N
};

std::array<std::uint8_t, kInfoReportSize> encode_info(const DeviceInfo& info);
std::optional<DeviceInfo> decode_info(std::span<const std::uint8_t> report);
std::array<std::uint8_t, kStateReportSize> encode_state(const StateReport& state);
std::optional<StateReport> decode_state(std::span<const std::uint8_t> report);
std::array<std::uint8_t, kForceReportSize> encode_force(const ForceReport& force);
std::optional<ForceReport> decode_force(std::span<const std::uint8_t> report);

}  // namespace vimg::hid_force
