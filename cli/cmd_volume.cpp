// `vimg volume make-study --seed N --out DIR` and `vimg volume probe SCENE --path P.csv --out F.csv`
// (docs/volume.md).
#include <cstdio>
#include <memory>
#include <string>

#include "cli/command.hpp"
#include "player/haptic/probe_render.hpp"
#include "primitives/volume/study_set.hpp"
#include "storage/atomic_file.hpp"
#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/print_diagnostics.hpp"
#include "storage/volume/study_writer.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg::cli {
namespace {

int make_study(std::uint64_t seed, const std::string& out) {
  const StudySet set = make_study_set(seed);
  if (auto error = write_study_set(set, out)) {
    std::fprintf(stderr, "vimg volume: %s\n", error->c_str());
    return kExitFailure;
  }
  std::printf("{\"bend_x_mm\":%s,\"plane_z_mm\":%s}\n", format_decimal(set.layout.bend_x_mm).c_str(),
              format_decimal(set.layout.plane_z_mm).c_str());
  return kExitOk;
}

int probe(const std::string& scene_path, const std::string& path_file, const std::string& out, bool allow_outside_files) {
  VolumeSceneLoadOptions load_options;
  load_options.allow_files_outside_scene_folder = allow_outside_files;
  VolumeSceneLoadResult loaded = load_volume_scene_file(scene_path, load_options);
  print_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) return kExitFailure;
  const ProbePathParseResult path = load_probe_path_file(path_file);
  print_diagnostics(path.diagnostics);
  if (!path.path) return kExitFailure;
  auto scene = build_haptic_scene(*loaded.loaded);
  const DeviceProfile& device = loaded.loaded->scene.device;
  const auto rows = render_probe_path(*scene, *path.path, device.rate_hz, device.max_force_N);
  // A new output takes the scene's permission bits (what it renders), as cp's copy.
  if (auto error = write_file_atomically(out, write_probe_forces_csv(rows), NewFileMode::of(scene_path))) {
    std::fprintf(stderr, "vimg volume: %s\n", error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void add_volume_command(CLI::App& vimg, int& exit_code) {
  CLI::App* volume = vimg.add_subcommand("volume", "volume haptics: write the study data set, or render forces along a probe path");
  volume->require_subcommand(1);

  CLI::App* study = volume->add_subcommand("make-study", "write the study data set (two NRRD volumes and a scene) into DIR");
  struct StudyArgs {
    std::uint64_t seed = 0;
    std::string out;
  };
  auto s = std::make_shared<StudyArgs>();
  study->add_option("--seed", s->seed, "random seed (a non-negative integer)")->required()->check(CLI::NonNegativeNumber);
  study->add_option("--out", s->out, "output folder (created if missing)")->required();
  study->callback([s, &exit_code] { exit_code = make_study(s->seed, s->out); });

  CLI::App* probe_cmd = volume->add_subcommand("probe", "render the forces along a probe path (CSV time_s,x_mm,y_mm,z_mm)");
  struct ProbeArgs {
    std::string scene, path, out;
    bool allow_outside_files = false;
  };
  auto p = std::make_shared<ProbeArgs>();
  probe_cmd->add_option("SCENE", p->scene, "a volume scene (.vscene.xml)")->required();
  probe_cmd->add_option("--path", p->path, "the probe path CSV")->required();
  probe_cmd->add_option("--out", p->out, "the force CSV to write (atomically)")->required();
  probe_cmd->add_flag("--allow-outside-files", p->allow_outside_files, "let the scene name data files outside its own folder (an absolute path, ..); off by default");
  probe_cmd->footer("Limits (docs/limits.md): a path of at most " + std::to_string(kMaxProbePathRows) + " rows and " +
                    std::to_string(static_cast<int>(kMaxProbePathDurationS)) + " s, coordinates within " +
                    std::to_string(static_cast<int>(kMaxProbeCoordinateMm)) + " mm; data files in the scene's folder (see --allow-outside-files).");
  probe_cmd->callback([p, &exit_code] { exit_code = probe(p->scene, p->path, p->out, p->allow_outside_files); });
}

}  // namespace vimg::cli
