#pragma once
// HID Haptics (usage page 0x0E), Simple Haptic Controller (usage 0x01): usages and the report
// layout this driver speaks. hidapi 0.13 cannot read report descriptors, so the layout is fixed
// (docs/hardware.md, "USB HID haptics"); a device with another layout is refused at connect().
//   Feature report kWaveformListReport: id, then up to kMaxWaveforms u16 LE waveform usages for
//     ordinals 3, 4, ... (ordinal 1 is WAVEFORM_NONE, 2 is WAVEFORM_STOP); 0 ends the list.
//   Feature report kDurationListReport: id, then a u16 LE duration in ms per listed waveform.
//   Output report kTriggerReport: id, ManualTrigger (ordinal, u8), Intensity (0..100, u8),
//     RepeatCount (u8), RetriggerPeriod (ms, u16 LE).
#include <cstdint>

namespace vimg::hid_haptics {

inline constexpr std::uint16_t kUsagePage = 0x0E;
inline constexpr std::uint16_t kSimpleHapticController = 0x01;

inline constexpr std::uint16_t kWaveformNone = 0x1001;
inline constexpr std::uint16_t kWaveformStop = 0x1002;
inline constexpr std::uint16_t kWaveformClick = 0x1003;
inline constexpr std::uint16_t kWaveformBuzz = 0x1004;
inline constexpr std::uint16_t kWaveformRumble = 0x1005;
inline constexpr std::uint16_t kWaveformPress = 0x1006;
inline constexpr std::uint16_t kWaveformRelease = 0x1007;

inline constexpr std::uint8_t kOrdinalStop = 2;
inline constexpr std::uint8_t kFirstDeviceOrdinal = 3;

inline constexpr std::uint8_t kWaveformListReport = 1;
inline constexpr std::uint8_t kDurationListReport = 2;
inline constexpr std::uint8_t kTriggerReport = 3;
inline constexpr int kMaxWaveforms = 16;
inline constexpr int kTriggerReportSize = 6;

}  // namespace vimg::hid_haptics
