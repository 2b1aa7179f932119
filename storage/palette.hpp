#pragma once
// One look for every view of a vibroimage: the PNG picture (storage/picture.cpp), the player
// (apps/vimg-player/image_view.cpp) and the editor's canvas take their colours and their texture
// stripes from here, so that a DOT, a LINE or a SURFACE looks the same wherever it is shown.
//   - colours per primitive kind: dots dark, lines coloured by frequency on a log scale from 20 Hz
//     (orange) through about 140 Hz (crimson) to 1000 Hz (violet), surfaces teal;
//   - a surface's texture runs across x: its opacity at x_mm follows its pattern at its period
//     (sine, square, triangle), so the stripes are vertical, as a finger moving along x feels them;
//   - opacity grows with gain, never to nothing: a gain of 0 is still visible.
// Pure functions and constants; no I/O, safe on any thread.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "primitives/image.hpp"

namespace vimg::palette {

struct Rgb8 {
  std::uint8_t r, g, b;
};

inline constexpr Rgb8 kBackground{255, 255, 255};  // the canvas
inline constexpr Rgb8 kCanvasBorder{120, 120, 120};
inline constexpr Rgb8 kDot{25, 25, 35};
inline constexpr Rgb8 kLineLow{240, 140, 0};    // 20 Hz and below: orange
inline constexpr Rgb8 kLineMid{220, 30, 90};    // about 140 Hz (the geometric middle): crimson
inline constexpr Rgb8 kLineHigh{110, 40, 200};  // 1000 Hz and above: violet
inline constexpr Rgb8 kSurface{20, 120, 150};   // teal
inline constexpr Rgb8 kHighlight{255, 200, 0};  // under the pointer or being touched: amber
inline constexpr Rgb8 kSelection{0, 110, 255};  // selected in the editor: blue
inline constexpr Rgb8 kWeakOnActuator{235, 0, 140};  // barely felt on the chosen actuator: magenta, dashed

inline constexpr double kLineLowHz = 20.0;
inline constexpr double kLineHighHz = 1000.0;

// a + (b - a) t, per channel, t in [0, 1].
inline Rgb8 mix(const Rgb8& a, const Rgb8& b, double t) {
  const auto channel = [t](std::uint8_t x, std::uint8_t y) {
    return static_cast<std::uint8_t>(std::lround(x + (static_cast<double>(y) - x) * std::clamp(t, 0.0, 1.0)));
  };
  return {channel(a.r, b.r), channel(a.g, b.g), channel(a.b, b.b)};
}

// A line's colour: log scale of its frequency from 20 Hz to 1000 Hz, orange to crimson to violet.
inline Rgb8 line_colour(double frequency_hz) {
  const double t = std::clamp(std::log(std::max(frequency_hz, kLineLowHz) / kLineLowHz) / std::log(kLineHighHz / kLineLowHz),
                              0.0, 1.0);
  return t < 0.5 ? mix(kLineLow, kLineMid, 2.0 * t) : mix(kLineMid, kLineHigh, 2.0 * t - 1.0);
}

// Opacity of a dot or a line of `gain` (0..1): 0.35 + 0.65 gain.
inline double stroke_opacity(double gain) { return 0.35 + 0.65 * std::clamp(gain, 0.0, 1.0); }

// The pattern's height in [0, 1] at phase u (in periods): sine 0.5 + 0.5 sin(2 pi u), square 1 for
// the first half period and 0 for the second, triangle rising then falling linearly.
inline double pattern_height(SurfacePattern pattern, double u) {
  const double frac = u - std::floor(u);
  switch (pattern) {
    case SurfacePattern::sine: return 0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * u);
    case SurfacePattern::square: return frac < 0.5 ? 1.0 : 0.0;
    case SurfacePattern::triangle: return frac < 0.5 ? 2.0 * frac : 2.0 - 2.0 * frac;
  }
  return 0.0;
}

// Opacity of a surface at x_mm: (0.25 + 0.75 gain)(0.3 + 0.7 height(x_mm / period_mm)). The
// stripes depend on x only: they run vertically on every view.
inline double surface_opacity(const Surface& s, double x_mm) {
  const double base = 0.25 + 0.75 * std::clamp(s.gain, 0.0, 1.0);
  const double period_mm = s.period_mm > 0.0 ? s.period_mm : 1.0;
  return base * (0.3 + 0.7 * pattern_height(s.pattern, x_mm / period_mm));
}

}  // namespace vimg::palette
