#pragma once
// The touch panel's latency each player assumes until the user sets it (--touch-latency-ms, the
// editor's setting, the page's setting): from the finger's contact to the event reaching the
// program. Sources and the whole budget: docs/latency.md.
//   - a touchscreen: 25 ms. Touch-down to kernel event measured 9.6 ms (Pixel) to 29.6 ms
//     (Nexus 7), kernel to app 1.1-3.3 ms (Google's WALT); 25 ms lies in that span.
//   - a mouse or a pen on a desktop: 8 ms, the worst polling interval of a USB HID mouse at
//     125 Hz (the common default rate).
// The output path's own latency is added by the player from its sink (DriveSink::output_latency_s).
namespace vimg {

inline constexpr double kDefaultTouchPanelLatency_s = 0.025;
inline constexpr double kDefaultMousePanelLatency_s = 0.008;
// The largest panel latency a player accepts (ms options are checked against it).
inline constexpr double kMaxTouchPanelLatency_s = 0.5;

}  // namespace vimg
