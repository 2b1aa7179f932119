#pragma once
// One line of a Linux input-event recording, in either of the two text forms touch devices are
// recorded in:
//   - evemu-record: `E: 12.345678 0003 0035 0539` (seconds.microseconds, type and code in hex,
//     value in decimal), after a header of `#` comments (`#     Event code 53 (ABS_MT_POSITION_X)`
//     then `#       Min 0` / `#       Max 799` / `#       Resolution 10`) and `N:`, `I:`, `P:`,
//     `B:`, `A: 35 0 799 0 0 10` lines (an axis: code in hex, min, max, fuzz, flat, resolution);
//   - Android `getevent -lt` (or `-t`): `[   12345.678901] /dev/input/event2: EV_ABS
//     ABS_MT_POSITION_X 000001a4` (names or hex numbers, value in hex, or DOWN/UP for keys),
//     with `add device` / `name:` lines and `getevent -lp` axis lines
//     (`ABS_MT_POSITION_X : value 0, min 0, max 1199, fuzz 0, flat 0, resolution 0`).
// EvdevLineReader turns each line into an event, an axis range or nothing; the trace reader
// (evdev_trace.hpp) makes fingers of the events.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace vimg {

namespace evdev {
inline constexpr int kEvSyn = 0, kEvKey = 1, kEvAbs = 3;
inline constexpr int kSynReport = 0, kSynMtReport = 2, kSynDropped = 3;
inline constexpr int kBtnTouch = 0x14a;
inline constexpr int kAbsX = 0x00, kAbsY = 0x01, kAbsPressure = 0x18;
inline constexpr int kAbsMtSlot = 0x2f, kAbsMtPositionX = 0x35, kAbsMtPositionY = 0x36;
inline constexpr int kAbsMtTrackingId = 0x39, kAbsMtPressure = 0x3a;
}  // namespace evdev

struct EvdevEvent {
  std::int64_t seconds = 0;       // whole seconds of the timestamp
  std::int64_t microseconds = 0;  // 0..999999
  int type = 0;
  int code = -1;  // -1: a code this reader does not know (its event is ignored)
  std::int64_t value = 0;
  std::string device;  // getevent's device path ("" for evemu)
};

struct EvdevAxisRange {
  int code = 0;
  std::int64_t min = 0;
  std::int64_t max = 0;
  std::int64_t resolution = 0;  // units per mm, 0 when unknown
};

struct EvdevLine {
  enum class Kind { nothing, event, axis, bad } kind = Kind::nothing;
  EvdevEvent event;
  EvdevAxisRange axis;
  std::string problem;  // for Kind::bad
};

class EvdevLineReader {
 public:
  EvdevLine read(std::string_view line);

 private:
  EvdevLine read_evemu_event(std::string_view rest) const;
  EvdevLine read_getevent(std::string_view line) const;
  EvdevLine read_comment(std::string_view comment);

  std::optional<EvdevAxisRange> described_;  // the axis an evemu `# Event code` comment describes
};

}  // namespace vimg
