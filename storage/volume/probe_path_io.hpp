#pragma once
// Probe paths and rendered forces as CSV (docs/volume.md).
//   input:  a header `time_s,x_mm,y_mm,z_mm`, then rows with strictly increasing time;
//   output: `time_s,x_mm,y_mm,z_mm,fx_N,fy_N,fz_N,kin_fx_N,kin_fy_N,kin_fz_N,vib_fx_N,vib_fy_N,vib_fz_N`
//           (total force clamped to the device limit, then its kinaesthetic and vibrotactile parts).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/vec3.hpp"
#include "storage/diagnostic.hpp"

namespace vimg {

struct ProbePathPoint {
  double time_s = 0.0;
  Vec3 position_m;
};

struct ProbePathParseResult {
  std::optional<std::vector<ProbePathPoint>> path;
  std::vector<Diagnostic> diagnostics;
};

// Refuses, with FILE:LINE, anything that is not a finite number, |time_s| over kMaxProbeTimeS,
// coordinates over kMaxProbeCoordinateMm, more than kMaxProbePathRows rows and a path lasting more
// than kMaxProbePathDurationS (storage/limits.hpp).
ProbePathParseResult parse_probe_path_csv(std::string_view text, const std::string& file_name);
// The same from a file, read through the bounded reader (at most kMaxCsvFileBytes; a FIFO, device
// or directory is refused as `FILE: error: ...`).
ProbePathParseResult load_probe_path_file(const std::filesystem::path& file);

// The rows a render of a path lasting `duration_s` at `rate_hz` produces, floor(duration x rate) + 1,
// or nothing when that is over kMaxProbeRenderRows or the numbers are not finite and positive (a
// zero duration is one row). A renderer checks it before reserving its rows.
std::optional<std::size_t> probe_render_rows(double duration_s, double rate_hz);

struct ProbeForceRow {
  double time_s = 0.0;
  Vec3 position_m;
  Vec3 total_N;
  Vec3 kinaesthetic_N;
  Vec3 vibrotactile_N;
};

std::string write_probe_forces_csv(const std::vector<ProbeForceRow>& rows);

}  // namespace vimg
