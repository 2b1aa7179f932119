#include "editor/editor_options.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>

namespace vimg::editor {
namespace {

constexpr const char* kUsage =
    "usage: vimg-editor [FILE] [options]\n"
    "  FILE                     a .vimg or .png vibrotactile image to open\n"
    "  --output OUT             playing-mode output (default audio): audio[:DEVICE], wav:FILE, csv:FILE,\n"
    "                           drv2605l:/dev/i2c-N[,en=CHIP:LINE], spi:/dev/spidevB.C, hid:VID:PID, none\n"
    "  --rate HZ                output sample rate (default 8000)\n"
    "  --recovery-dir DIR       where autosave keeps the recovery file\n"
    "  --autosave-interval S    seconds between autosaves of unsaved changes (default 5)\n"
    "  --library-dir DIR        your library folder (default ~/vibroimages)\n"
    "  --zoom Z                 initial zoom, 1 = physical size (default 1)\n"
    "  --px-per-mm D            screen density (default: from the display)\n"
    "  --size WxH               window size in pixels (default 1280x800)\n"
    "  --play                   start in playing mode\n"
    "  --record-gesture FILE    record the gesture in playing mode and write it to FILE (CSV)\n"
    "  --print-layout           print canvas and widget positions on stdout (scripted tests)\n"
    "  --benchmark-frames N     draw N frames as fast as possible, print frame times, exit\n"
    "  --help, --version\n";

bool parse_double(std::string_view text, double& out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

bool parse_int(std::string_view text, int& out) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && ptr == end;
}

ParsedOptions usage_error(const std::string& problem) {
  return ParsedOptions{std::nullopt, 2, "vimg-editor: " + problem + "\n" + kUsage};
}

}  // namespace

ParsedOptions parse_editor_options(int argc, char** argv) {
  EditorOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    auto value = [&](std::string_view& out) {
      if (i + 1 >= argc) return false;
      out = argv[++i];
      return true;
    };
    std::string_view v;
    if (arg == "--help" || arg == "-h") return ParsedOptions{std::nullopt, 0, kUsage};
    if (arg == "--version") return ParsedOptions{std::nullopt, 0, std::string("vimg-editor ") + VIMG_VERSION + "\n"};
    if (arg == "--play") {
      o.play_at_start = true;
    } else if (arg == "--print-layout") {
      o.print_layout = true;
    } else if (arg == "--output") {
      if (!value(v)) return usage_error("--output needs a value");
      OutputChoiceResult parsed = parse_output_choice(std::string(v));
      if (!parsed.choice) return usage_error(parsed.error);
      o.output = *parsed.choice;
    } else if (arg == "--rate") {
      if (!value(v) || !parse_double(v, o.sample_rate_hz) || o.sample_rate_hz < 1 || o.sample_rate_hz > 48000) {
        return usage_error("--rate needs a number of Hz in [1, 48000]");
      }
    } else if (arg == "--recovery-dir") {
      if (!value(v)) return usage_error("--recovery-dir needs a folder");
      o.recovery_dir = v;
    } else if (arg == "--library-dir") {
      if (!value(v)) return usage_error("--library-dir needs a folder");
      o.library_dir = v;
    } else if (arg == "--record-gesture") {
      if (!value(v)) return usage_error("--record-gesture needs a file");
      o.record_gesture = v;
    } else if (arg == "--autosave-interval") {
      if (!value(v) || !parse_double(v, o.autosave_interval_s) || o.autosave_interval_s <= 0) {
        return usage_error("--autosave-interval needs a positive number of seconds");
      }
    } else if (arg == "--zoom") {
      if (!value(v) || !parse_double(v, o.zoom) || o.zoom <= 0) return usage_error("--zoom needs a positive number");
    } else if (arg == "--px-per-mm") {
      if (!value(v) || !parse_double(v, o.px_per_mm) || o.px_per_mm <= 0) {
        return usage_error("--px-per-mm needs a positive number");
      }
    } else if (arg == "--size") {
      if (!value(v)) return usage_error("--size needs WxH");
      const auto x = v.find('x');
      if (x == std::string_view::npos || !parse_int(v.substr(0, x), o.width_px) ||
          !parse_int(v.substr(x + 1), o.height_px) || o.width_px < 320 || o.height_px < 240) {
        return usage_error("--size needs WxH, at least 320x240");
      }
    } else if (arg == "--benchmark-frames") {
      if (!value(v) || !parse_int(v, o.benchmark_frames) || o.benchmark_frames <= 0) {
        return usage_error("--benchmark-frames needs a positive count");
      }
    } else if (!arg.empty() && arg[0] == '-') {
      return usage_error("unknown option '" + std::string(arg) + "'");
    } else if (o.file.empty()) {
      o.file = arg;
    } else {
      return usage_error("only one FILE can be opened");
    }
  }
  return ParsedOptions{o, 0, ""};
}

}  // namespace vimg::editor
