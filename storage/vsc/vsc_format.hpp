#pragma once
// The compact compiled image (.vsc): what the browser loads instead of the .vimg XML, because the
// XML reader (tinyxml2) is not built into the WebAssembly renderer (docs/web.md). The native side
// reads the .vimg with the normal reader (storage/image_io.hpp) and writes this form; the wasm
// reads it back into the same Image (primitives/image.hpp) and compiles it with compile_scene, so
// both render from equal values. Only what the renderer uses is kept: the canvas, the interaction
// parameters, the primitive tree (ids, every parameter, groups and their names) and the actuator
// response; meta data, unknown elements and unknown attributes are left out.
//
// Layout, version 1. Little-endian throughout; f64 is an IEEE 754 double, str is a u32 byte count
// followed by that many bytes (UTF-8, at most kVscMaxStringBytes).
//   header      u8[8] magic "VIMGVSC\0", u32 format version (1), u32 byte count of the rest
//   actuator    u8 response model (0 ideal, 1 lra, 2 erm, 3 voice_coil),
//               f64 resonance_hz, q, low_hz, high_hz, spin_up_s, spin_down_s
//   canvas      i32 version_major, i32 version_minor, f64 width_mm, f64 height_mm
//   interaction u8 present (0|1); when 1: f64 mass_kg, full_speed_mm_per_s, max_deformation_mm
//   elements    u32 count, then that many elements in paint order
//   element     str id, u8 kind, then by kind:
//     0 dot     f64 x_mm, y_mm, radius_mm, gain
//     1 line    f64 x1_mm, y1_mm, x2_mm, y2_mm, width_mm, frequency_hz, damping, gain
//     2 surface u8 shape (0 rect, 1 ellipse, 2 polygon), u8 pattern (0 sine, 1 square, 2 triangle),
//               f64 x_mm, y_mm, width_mm, height_mm, cx_mm, cy_mm, rx_mm, ry_mm, period_mm,
//               relief_mm, gain, u32 point count, then per point f64 x_mm, y_mm
//     3 group   u8 named (0|1), str name when named, u32 child count, then the children
// The reader refuses anything else: a wrong magic or version, a count beyond the bytes left or the
// format's limits (storage/limits.hpp), a number outside the range the parameter table gives
// (storage/parameter_table.hpp, as the XML reader checks them), groups deeper than kMaxGroupDepth,
// or bytes left over at the end.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace vimg::vsc {

inline constexpr std::string_view kMagic{"VIMGVSC\0", 8};
inline constexpr std::uint32_t kFormatVersion = 1;
inline constexpr std::size_t kHeaderBytes = 16;
inline constexpr std::size_t kMaxStringBytes = 4096;
// The file as a whole: the largest .vimg (storage/limits.hpp kMaxImageFileBytes) compiles to less.
inline constexpr std::size_t kMaxFileBytes = std::size_t{64} << 20;

enum class ElementKind : std::uint8_t { dot = 0, line = 1, surface = 2, group = 3 };

}  // namespace vimg::vsc
