#include "storage/volume/probe_path_io.hpp"

#include <cmath>

#include "storage/csv_lines.hpp"
#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/load_file.hpp"

namespace vimg {

namespace {

constexpr const char* kColumns[] = {"time_s", "x_mm", "y_mm", "z_mm"};

std::string limit_text(double limit) { return format_decimal(limit); }

}  // namespace

ProbePathParseResult parse_probe_path_csv(std::string_view text, const std::string& file_name) {
  ProbePathParseResult result;
  std::vector<ProbePathPoint> path;
  DiagnosticList list(file_name);
  auto error = [&](int line, std::string_view message) { list.error(line, message); };
  CsvLines lines(text, {.max_rows = kMaxProbePathRows});
  const std::optional<std::string_view> header = lines.header();
  if (header && *header != "time_s,x_mm,y_mm,z_mm") error(lines.line(), "the header must be 'time_s,x_mm,y_mm,z_mm'");
  while (const std::optional<std::string_view> next = lines.row()) {
    const int line = lines.line();
    std::string_view row = *next;
    double v[4];
    int n = 0;
    bool bad = false;
    while (!bad) {
      const std::size_t comma = row.find(',');
      const std::string_view cell = row.substr(0, comma);
      if (n == 4) {
        error(line, "more than 4 columns");
        bad = true;
        break;
      }
      const ParsedNumber parsed = parse_decimal(cell);
      if (const auto* why = std::get_if<std::string>(&parsed)) {
        error(line, "column " + std::to_string(n + 1) + ": '" + escape_input(cell) + "' " + *why);
        bad = true;
        break;
      }
      const double value = std::get<double>(parsed);
      const double limit = n == 0 ? kMaxProbeTimeS : kMaxProbeCoordinateMm;
      if (std::abs(value) > limit) {
        error(line, "column " + std::to_string(n + 1) + " (" + kColumns[n] + ") '" + escape_input(cell) + "' is beyond " +
                        limit_text(limit) + (n == 0 ? " s" : " mm") + " (limit " + limit_text(limit) + ")");
        bad = true;
        break;
      }
      v[n++] = value;
      if (comma == std::string_view::npos) break;
      row.remove_prefix(comma + 1);
    }
    if (bad) continue;
    if (n != 4) {
      error(line, "expected 4 columns, got " + std::to_string(n));
      continue;
    }
    if (!path.empty() && !(v[0] > path.back().time_s)) {
      error(line, "time must increase strictly");
      continue;
    }
    if (!path.empty() && v[0] - path.front().time_s > kMaxProbePathDurationS) {
      error(line, "the path lasts more than " + limit_text(kMaxProbePathDurationS) + " s (limit " +
                      limit_text(kMaxProbePathDurationS) + ")");
      break;
    }
    path.push_back({v[0], Vec3{v[1], v[2], v[3]} * 1e-3});
  }
  if (lines.past_row_limit()) error(lines.line(), lines.row_limit_problem());
  if (!header) error(0, "empty file, expected the header 'time_s,x_mm,y_mm,z_mm'");
  else if (path.empty() && !list.has_errors()) error(lines.line(), "the path has no rows");
  if (!list.has_errors()) result.path = std::move(path);
  result.diagnostics = list.take();
  return result;
}

ProbePathParseResult load_probe_path_file(const std::filesystem::path& file) {
  return load_file<ProbePathParseResult>(file, kMaxCsvFileBytes, parse_probe_path_csv);
}

std::optional<std::size_t> probe_render_rows(double duration_s, double rate_hz) {
  if (!(duration_s >= 0.0) || !(rate_hz > 0.0) || !std::isfinite(duration_s) || !std::isfinite(rate_hz)) return std::nullopt;
  const double steps = std::floor(duration_s * rate_hz + 1e-9) + 1.0;
  if (!(steps <= static_cast<double>(kMaxProbeRenderRows))) return std::nullopt;
  return static_cast<std::size_t>(steps);
}

std::string write_probe_forces_csv(const std::vector<ProbeForceRow>& rows) {
  std::string out = "time_s,x_mm,y_mm,z_mm,fx_N,fy_N,fz_N,kin_fx_N,kin_fy_N,kin_fz_N,vib_fx_N,vib_fy_N,vib_fz_N\n";
  auto add3 = [&](const Vec3& v, double scale) {
    out += "," + format_decimal(v.x * scale) + "," + format_decimal(v.y * scale) + "," + format_decimal(v.z * scale);
  };
  for (const auto& r : rows) {
    out += format_decimal(r.time_s);
    add3(r.position_m, 1e3);
    add3(r.total_N, 1.0);
    add3(r.kinaesthetic_N, 1.0);
    add3(r.vibrotactile_N, 1.0);
    out += "\n";
  }
  return out;
}

}  // namespace vimg
