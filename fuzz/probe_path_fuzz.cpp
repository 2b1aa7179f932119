// Fuzzes the probe-path CSV reader: any bytes give located errors or a path within every limit of
// storage/limits.hpp, never a crash; every message is printable and bounded.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "storage/limits.hpp"
#include "storage/volume/probe_path_io.hpp"

namespace {

void check_message(const vimg::Diagnostic& d) {
  if (d.file != "fuzz.csv" || d.message.size() > vimg::kMaxMessageBytes) std::abort();
  for (const char c : d.to_string()) {
    const auto b = static_cast<unsigned char>(c);
    if (b < 0x20 || b == 0x7F) std::abort();  // a control character reached the terminal
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::ProbePathParseResult r = vimg::parse_probe_path_csv(text, "fuzz.csv");
  if (r.path.has_value() == vimg::has_errors(r.diagnostics)) std::abort();  // a path iff no error
  if (r.diagnostics.size() > vimg::kMaxDiagnosticsPerFile + 1) std::abort();
  for (const auto& d : r.diagnostics) check_message(d);
  if (!r.path) return 0;
  const auto& path = *r.path;
  if (path.empty() || path.size() > vimg::kMaxProbePathRows) std::abort();
  for (std::size_t i = 0; i < path.size(); ++i) {
    const auto& p = path[i];
    if (!std::isfinite(p.time_s) || std::abs(p.time_s) > vimg::kMaxProbeTimeS) std::abort();
    if (i > 0 && !(p.time_s > path[i - 1].time_s)) std::abort();
    for (const double c : {p.position_m.x, p.position_m.y, p.position_m.z}) {
      if (!(std::abs(c) <= vimg::kMaxProbeCoordinateMm * 1e-3 * (1 + 1e-12))) std::abort();
    }
  }
  const double duration_s = path.back().time_s - path.front().time_s;
  if (duration_s > vimg::kMaxProbePathDurationS) std::abort();
  if (!vimg::probe_render_rows(duration_s, vimg::kMaxDeviceRateHz)) std::abort();  // every valid path renders
  return 0;
}
