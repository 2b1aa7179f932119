#pragma once
// The render rate and the live finger count, in one place for every player, command and the page
// (the wasm hands them to web/wasm/vimg_api.js): vimg render, vimg-player, the editor, the
// offline and the real-time renderers.
namespace vimg {

inline constexpr double kDefaultRenderRateHz = 8000.0;  // the spec's default (format section 4)
inline constexpr double kMinRenderRateHz = 1.0;
inline constexpr double kMaxRenderRateHz = 48000.0;
// Fingers a live player follows at once (the tracker's, the editor's trail).
inline constexpr int kMaxLiveFingers = 10;

inline constexpr bool valid_render_rate(double rate_hz) {
  return rate_hz >= kMinRenderRateHz && rate_hz <= kMaxRenderRateHz;
}

}  // namespace vimg
