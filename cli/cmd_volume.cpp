// `vimg volume make-study --seed N --out DIR` and `vimg volume probe SCENE --path P.csv --out F.csv`
// (docs/volume.md).
#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "cli/command.hpp"
#include "player/haptic/probe_render.hpp"
#include "primitives/volume/study_set.hpp"
#include "storage/atomic_file.hpp"
#include "storage/number_text.hpp"
#include "storage/volume/study_writer.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg::cli {
namespace {

constexpr const char* kUsage =
    "usage: vimg volume make-study --seed N --out DIR\n"
    "       vimg volume probe SCENE --path P.csv --out F.csv\n";

int usage(const char* problem) {
  std::fprintf(stderr, "vimg volume: %s\n%s", problem, kUsage);
  return kExitUsage;
}

void print_diagnostics(const std::vector<Diagnostic>& diagnostics) {
  for (const auto& d : diagnostics) std::fprintf(stderr, "%s\n", d.to_string().c_str());
}

int make_study(std::span<const std::string_view> args) {
  std::optional<std::uint64_t> seed;
  std::string out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--seed" && i + 1 < args.size()) {
      const std::string_view s = args[++i];
      std::uint64_t v = 0;
      const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
      if (ec != std::errc() || end != s.data() + s.size()) return usage("--seed needs a non-negative integer");
      seed = v;
    } else if (args[i] == "--out" && i + 1 < args.size()) {
      out = std::string(args[++i]);
    } else {
      return usage(("unexpected argument '" + std::string(args[i]) + "'").c_str());
    }
  }
  if (!seed || out.empty()) return usage("make-study needs --seed N and --out DIR");
  const StudySet set = make_study_set(*seed);
  if (auto error = write_study_set(set, out)) {
    std::fprintf(stderr, "vimg volume: %s\n", error->c_str());
    return kExitFailure;
  }
  std::printf("{\"bend_x_mm\":%s,\"plane_z_mm\":%s}\n", format_decimal(set.layout.bend_x_mm).c_str(),
              format_decimal(set.layout.plane_z_mm).c_str());
  return kExitOk;
}

int probe(std::span<const std::string_view> args) {
  std::string scene_path, path_file, out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--path" && i + 1 < args.size()) path_file = std::string(args[++i]);
    else if (args[i] == "--out" && i + 1 < args.size()) out = std::string(args[++i]);
    else if (!args[i].starts_with("--") && scene_path.empty()) scene_path = std::string(args[i]);
    else return usage(("unexpected argument '" + std::string(args[i]) + "'").c_str());
  }
  if (scene_path.empty() || path_file.empty() || out.empty()) return usage("probe needs SCENE, --path P.csv and --out F.csv");
  VolumeSceneLoadResult loaded = load_volume_scene_file(scene_path);
  print_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) return kExitFailure;
  std::ifstream in(path_file, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "%s: error: cannot open file\n", path_file.c_str());
    return kExitFailure;
  }
  std::ostringstream text;
  text << in.rdbuf();
  const ProbePathParseResult path = parse_probe_path_csv(text.str(), path_file);
  print_diagnostics(path.diagnostics);
  if (!path.path) return kExitFailure;
  auto scene = build_haptic_scene(*loaded.loaded);
  const DeviceProfile& device = loaded.loaded->scene.device;
  const auto rows = render_probe_path(*scene, *path.path, device.rate_hz, device.max_force_N);
  if (auto error = write_file_atomically(out, write_probe_forces_csv(rows))) {
    std::fprintf(stderr, "vimg volume: %s\n", error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

int volume_command(std::span<const std::string_view> args) {
  if (args.empty()) return usage("missing subcommand");
  if (args[0] == "make-study") return make_study(args.subspan(1));
  if (args[0] == "probe") return probe(args.subspan(1));
  if (args[0] == "--help" || args[0] == "-h") {
    std::printf("%s", kUsage);
    return kExitOk;
  }
  return usage(("unknown subcommand '" + std::string(args[0]) + "'").c_str());
}

}  // namespace vimg::cli
