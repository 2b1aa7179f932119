// `vimg gesture (line|arc|circle) ... --out G.csv`: synthesises a gesture file from a path.
// `vimg gesture import TRACE --out G.csv [--panel-mm WxH | --px-per-mm K]`: a touch recording
// (evemu-record or Android getevent -lt text) as a gesture file.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cli/command.hpp"
#include "storage/gesture_csv.hpp"
#include "player/gesture_synth.hpp"
#include "player/touch_trace_gesture.hpp"
#include "storage/atomic_file.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::cli {

namespace {

struct GestureArgs {
  PathSpec path;
  SamplingSpec sampling;
  std::string from, to, center;  // X,Y in mm
  double jitter_ms = 0.0;
  std::string out, merge;
};

int run_gesture(GestureArgs& a) {
  PathSpec& path = a.path;
  SamplingSpec& sampling = a.sampling;
  const std::string& out = a.out;
  const std::string& merge = a.merge;
  cmdline::parse_point_2d(a.from, path.x0_mm, path.y0_mm);
  cmdline::parse_point_2d(a.to, path.x1_mm, path.y1_mm);
  cmdline::parse_point_2d(a.center, path.cx_mm, path.cy_mm);
  sampling.time_jitter_s = a.jitter_ms * 1e-3;
  if (auto problem = check_synthesis(path, sampling)) return usage_error("vimg gesture", *problem);

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
  // Merged into a gesture file: a new output takes that file's permission bits, as cp's copy.
  if (const auto error = write_file_atomically(out, text, merge.empty() ? NewFileMode{} : NewFileMode::of(merge))) {
    std::fprintf(stderr, "vimg gesture: %s\n", error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

struct ImportArgs {
  std::string trace, out, panel_mm;
  double px_per_mm = 0.0;
};

// "W x H" with x, X, the sign × or a comma between two finite numbers.
std::string panel_as_point(std::string text) {
  for (const std::string sep : {"\xC3\x97", "x", "X"}) {
    const std::size_t at = text.find(sep);
    if (at != std::string::npos) return text.replace(at, sep.size(), ",");
  }
  return text;
}

int run_import(const ImportArgs& a) {
  TouchMapping mapping;
  if (!a.panel_mm.empty()) {
    double w = 0.0, h = 0.0;
    cmdline::parse_point_2d(panel_as_point(a.panel_mm), w, h);
    mapping.panel_width_mm = w;
    mapping.panel_height_mm = h;
  }
  if (a.px_per_mm > 0.0) mapping.units_per_mm = a.px_per_mm;
  const TouchTraceParseResult trace = load_touch_trace(a.trace);
  print_diagnostics(trace.diagnostics);
  if (!trace.trace) return kExitFailure;
  const TraceGestureResult converted = trace_to_gesture(*trace.trace, mapping, a.trace);
  if (!converted.usage_problem.empty()) return usage_error("vimg gesture import", converted.usage_problem);
  for (const auto& e : converted.errors) std::fprintf(stderr, "%s\n", e.c_str());
  if (!converted.gesture) return kExitFailure;
  const std::string text = write_gesture_csv(*converted.gesture);
  const GestureParseResult check = parse_gesture_csv(text, a.out);  // what is written must read back
  if (!check.ok()) {
    for (const auto& e : check.errors) std::fprintf(stderr, "%s\n", e.c_str());
    return kExitFailure;
  }
  // A new output takes the recording's permission bits, as cp's copy.
  if (const auto error = write_file_atomically(a.out, text, NewFileMode::of(a.trace))) {
    std::fprintf(stderr, "vimg gesture import: %s\n", error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

void add_gesture_import(CLI::App& gesture, int& exit_code) {
  CLI::App* sub = gesture.add_subcommand(
      "import", "a touch recording (evemu-record, or Android getevent -lt text) as a gesture file; "
                "multi-touch protocol A or B, one finger per slot or contact");
  auto a = std::make_shared<ImportArgs>();
  sub->add_option("TRACE", a->trace, "the recording")->required();
  sub->add_option("--out", a->out, "output gesture file (written atomically)")->required();
  auto* panel = sub->add_option("--panel-mm", a->panel_mm,
                                "the touch area in mm, WxH: the recording's axis ranges map onto it")
                    ->check(CLI::Validator(
                        [](std::string& input) -> std::string {
                          double w = 0.0, h = 0.0;
                          if (!cmdline::parse_point_2d(panel_as_point(input), w, h) || !(w > 0.0) || !(h > 0.0) ||
                              w > kMaxGestureCoordinateMm || h > kMaxGestureCoordinateMm) {
                            return "'" + input + "' is not WxH with two positive sizes in mm";
                          }
                          return {};
                        },
                        "WxH"));
  sub->add_option("--px-per-mm", a->px_per_mm, "digitizer units per mm (instead of --panel-mm)")
      ->check(cmdline::finite_in(1e-6, 1e9))
      ->excludes(panel);
  sub->footer("Without --panel-mm or --px-per-mm, the device's own resolution (evemu's Resolution) is used; "
              "a recording without one needs either option. Times start at the recording's first event.");
  sub->callback([a, &exit_code] { exit_code = run_import(*a); });
}

}  // namespace

void add_gesture_command(CLI::App& vimg, int& exit_code) {
  CLI::App* gesture = vimg.add_subcommand("gesture", "synthesise a gesture file from a path at a given speed and event rate");
  gesture->require_subcommand(1);
  add_gesture_import(*gesture, exit_code);
  add_gesture_predict(*gesture, exit_code);
  gesture->footer("Angles: degrees, 0 along +x, increasing towards +y (y points down).");
  struct Kind {
    const char* name;
    PathSpec::Kind kind;
    const char* help;
  };
  for (const Kind& k : {Kind{"line", PathSpec::Kind::line, "a straight stroke from --from to --to"},
                        Kind{"arc", PathSpec::Kind::arc, "an arc around --center from --start to --end degrees"},
                        Kind{"circle", PathSpec::Kind::circle, "a full circle around --center, from --start degrees"}}) {
    CLI::App* sub = gesture->add_subcommand(k.name, k.help);
    auto a = std::make_shared<GestureArgs>();
    a->path.kind = k.kind;
    const double kFar = 1e6;  // mm, s, Hz: beyond any screen or recording
    if (k.kind == PathSpec::Kind::line) {
      sub->add_option("--from", a->from, "start point X,Y in mm")->required()->check(cmdline::point_2d());
      sub->add_option("--to", a->to, "end point X,Y in mm")->required()->check(cmdline::point_2d());
    } else {
      sub->add_option("--center", a->center, "centre X,Y in mm")->required()->check(cmdline::point_2d());
      sub->add_option("--radius", a->path.radius_mm, "radius in mm")->required()->check(cmdline::finite_in(0.0, kFar));
      auto* start = sub->add_option("--start", a->path.start_deg, "start angle in degrees")->check(cmdline::finite_in(-kFar, kFar));
      if (k.kind == PathSpec::Kind::arc) {
        start->required();
        sub->add_option("--end", a->path.end_deg, "end angle in degrees")->required()->check(cmdline::finite_in(-kFar, kFar));
      }
    }
    sub->add_option("--out", a->out, "output gesture file (written atomically)")->required();
    sub->add_option("--speed", a->sampling.speed_mm_per_s, "finger speed along the path, mm/s")->check(cmdline::finite_in(0.0, kFar));
    sub->add_option("--rate", a->sampling.event_rate_hz, "touch events per second")->check(cmdline::finite_in(0.0, kFar));
    sub->add_option("--at", a->sampling.start_time_s, "time of the down row, s")->check(cmdline::finite_in(0.0, kFar));
    sub->add_option("--hold", a->sampling.hold_s, "rest at the end before lifting, s")->check(cmdline::finite_in(0.0, kFar));
    sub->add_option("--finger", a->sampling.finger, "finger index")->check(CLI::Range(0, kMaxGestureFinger));
    sub->add_option("--pressure", a->sampling.pressure, "pressure in [0, 1]")->check(cmdline::finite_in(0.0, 1.0));
    sub->add_option("--jitter-ms", a->jitter_ms, "event timing jitter, peak to peak, ms")->check(cmdline::finite_in(0.0, kFar));
    sub->add_option("--jitter-mm", a->sampling.position_jitter_mm, "position noise, standard deviation, mm")
        ->check(cmdline::finite_in(0.0, kFar));
    sub->add_option("--seed", a->sampling.seed, "random seed for the jitter")->check(CLI::Range(0.0, 4294967295.0));
    sub->add_option("--merge", a->merge, "add the strokes of an existing gesture (multi-finger gestures)");
    sub->callback([a, &exit_code] { exit_code = run_gesture(*a); });
  }
}

}  // namespace vimg::cli
