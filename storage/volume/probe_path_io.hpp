#pragma once
// Probe paths and rendered forces as CSV (docs/volume.md).
//   input:  a header `time_s,x_mm,y_mm,z_mm`, then rows with strictly increasing time;
//   output: `time_s,x_mm,y_mm,z_mm,fx_N,fy_N,fz_N,kin_fx_N,kin_fy_N,kin_fz_N,vib_fx_N,vib_fy_N,vib_fz_N`
//           (total force clamped to the device limit, then its kinaesthetic and vibrotactile parts).
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

ProbePathParseResult parse_probe_path_csv(std::string_view text, const std::string& file_name);

struct ProbeForceRow {
  double time_s = 0.0;
  Vec3 position_m;
  Vec3 total_N;
  Vec3 kinaesthetic_N;
  Vec3 vibrotactile_N;
};

std::string write_probe_forces_csv(const std::vector<ProbeForceRow>& rows);

}  // namespace vimg
