// `vimg gesture (line|arc|circle) ... --out G.csv`: synthesises a gesture file from a path.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <string_view>

#include "cli/command.hpp"
#include "player/gesture.hpp"
#include "player/gesture_synth.hpp"

namespace vimg::cli {

namespace {

constexpr std::string_view kGestureHelp =
    "usage:\n"
    "  vimg gesture line   --from X,Y --to X,Y                         [common options]\n"
    "  vimg gesture arc    --center X,Y --radius R --start DEG --end DEG [common options]\n"
    "  vimg gesture circle --center X,Y --radius R [--start DEG]        [common options]\n"
    "common options:\n"
    "  --out G.csv          output gesture file (required; written atomically)\n"
    "  --speed MM_PER_S     finger speed along the path (default 100)\n"
    "  --rate HZ            touch events per second (default 120)\n"
    "  --at SECONDS         time of the down row (default 0)\n"
    "  --hold SECONDS       rest at the end before lifting (default 0)\n"
    "  --finger N           finger index (default 0)\n"
    "  --pressure P         pressure in [0,1] (default 1)\n"
    "  --jitter-ms MS       event timing jitter, peak to peak (default 0)\n"
    "  --jitter-mm MM       position noise, standard deviation (default 0)\n"
    "  --seed N             random seed for the jitter (default 1)\n"
    "  --merge G.csv        add the strokes of an existing gesture (multi-finger gestures)\n"
    "angles: degrees, 0 along +x, increasing towards +y (y points down)\n";

int usage_error(const std::string& problem) {
  std::fprintf(stderr, "vimg gesture: %s\n%.*s", problem.c_str(), static_cast<int>(kGestureHelp.size()),
               kGestureHelp.data());
  return kExitUsage;
}

bool parse_double(std::string_view s, double& out) {
  if (s.empty()) return false;
  if (s.front() == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc{} && r.ptr == s.data() + s.size() && std::isfinite(out);
}

bool parse_point(std::string_view s, double& x, double& y) {
  const auto comma = s.find(',');
  return comma != std::string_view::npos && parse_double(s.substr(0, comma), x) &&
         parse_double(s.substr(comma + 1), y);
}

bool write_atomically(const std::filesystem::path& path, const std::string& text, std::string& error) {
  std::filesystem::path temp = path;
  temp += ".tmp-" + std::to_string(std::random_device{}() % 1000000u);
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      error = path.string() + ": cannot write the gesture file";
      std::error_code ec;
      std::filesystem::remove(temp, ec);
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    error = path.string() + ": cannot rename the gesture file into place: " + ec.message();
    std::filesystem::remove(temp, ec);
    return false;
  }
  return true;
}

int run_gesture(std::span<const std::string_view> args) {
  if (args.empty()) return usage_error("missing the path kind (line, arc or circle)");
  if (args[0] == "--help" || args[0] == "-h") {
    std::fwrite(kGestureHelp.data(), 1, kGestureHelp.size(), stdout);
    return kExitOk;
  }
  PathSpec path;
  if (args[0] == "line") path.kind = PathSpec::Kind::line;
  else if (args[0] == "arc") path.kind = PathSpec::Kind::arc;
  else if (args[0] == "circle") path.kind = PathSpec::Kind::circle;
  else return usage_error("unknown path kind '" + std::string(args[0]) + "' (line, arc or circle)");

  SamplingSpec sampling;
  std::string out, merge;
  bool has_from = false, has_to = false, has_center = false, has_radius = false, has_start = false,
       has_end = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string_view a = args[i];
    if (i + 1 >= args.size()) return usage_error("option '" + std::string(a) + "' needs a value");
    const std::string_view v = args[++i];
    auto bad = [&] { return usage_error("bad value '" + std::string(v) + "' for " + std::string(a)); };
    double d = 0.0;
    if (a == "--from") {
      if (!parse_point(v, path.x0_mm, path.y0_mm)) return bad();
      has_from = true;
    } else if (a == "--to") {
      if (!parse_point(v, path.x1_mm, path.y1_mm)) return bad();
      has_to = true;
    } else if (a == "--center") {
      if (!parse_point(v, path.cx_mm, path.cy_mm)) return bad();
      has_center = true;
    } else if (a == "--radius") {
      if (!parse_double(v, path.radius_mm)) return bad();
      has_radius = true;
    } else if (a == "--start") {
      if (!parse_double(v, path.start_deg)) return bad();
      has_start = true;
    } else if (a == "--end") {
      if (!parse_double(v, path.end_deg)) return bad();
      has_end = true;
    } else if (a == "--out") {
      out = std::string(v);
    } else if (a == "--merge") {
      merge = std::string(v);
    } else if (a == "--speed") {
      if (!parse_double(v, sampling.speed_mm_per_s)) return bad();
    } else if (a == "--rate") {
      if (!parse_double(v, sampling.event_rate_hz)) return bad();
    } else if (a == "--at") {
      if (!parse_double(v, sampling.start_time_s)) return bad();
    } else if (a == "--hold") {
      if (!parse_double(v, sampling.hold_s)) return bad();
    } else if (a == "--pressure") {
      if (!parse_double(v, sampling.pressure)) return bad();
    } else if (a == "--finger") {
      if (!parse_double(v, d) || d != std::floor(d) || d < 0 || d > kMaxGestureFinger) return bad();
      sampling.finger = static_cast<int>(d);
    } else if (a == "--jitter-ms") {
      if (!parse_double(v, d)) return bad();
      sampling.time_jitter_s = d * 1e-3;
    } else if (a == "--jitter-mm") {
      if (!parse_double(v, sampling.position_jitter_mm)) return bad();
    } else if (a == "--seed") {
      if (!parse_double(v, d) || d != std::floor(d) || d < 0 || d > 4294967295.0) return bad();
      sampling.seed = static_cast<std::uint32_t>(d);
    } else {
      return usage_error("unknown option '" + std::string(a) + "'");
    }
  }
  if (out.empty()) return usage_error("missing --out G.csv");
  if (path.kind == PathSpec::Kind::line && !(has_from && has_to)) return usage_error("a line needs --from and --to");
  if (path.kind != PathSpec::Kind::line && !(has_center && has_radius))
    return usage_error("an arc or circle needs --center and --radius");
  if (path.kind == PathSpec::Kind::arc && !(has_start && has_end)) return usage_error("an arc needs --start and --end");
  if (auto problem = check_synthesis(path, sampling)) return usage_error(*problem);

  Gesture gesture;
  if (!merge.empty()) {
    GestureParseResult loaded = load_gesture_file(merge);
    for (const auto& e : loaded.errors) std::fprintf(stderr, "%s\n", e.c_str());
    if (!loaded.ok()) return kExitFailure;
    gesture = std::move(*loaded.gesture);
  }
  gesture.strokes.push_back(synthesise_stroke(path, sampling));
  const std::string text = write_gesture_csv(gesture);
  // The result must itself be a valid gesture (e.g. a merged finger must not be down twice).
  const GestureParseResult check = parse_gesture_csv(text, out);
  if (!check.ok()) {
    std::fprintf(stderr, "vimg gesture: the new stroke conflicts with the merged gesture (finger %d)\n",
                 sampling.finger);
    for (const auto& e : check.errors) std::fprintf(stderr, "%s\n", e.c_str());
    return kExitFailure;
  }
  std::string error;
  if (!write_atomically(out, text, error)) {
    std::fprintf(stderr, "vimg gesture: %s\n", error.c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

int gesture_command(std::span<const std::string_view> args) { return run_gesture(args); }

}  // namespace vimg::cli
