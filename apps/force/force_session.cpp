#include "apps/force/force_session.hpp"

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "apps/force/loop_run.hpp"
#include "apps/force/status_line.hpp"
#include "cmdline/exit_codes.hpp"
#include "hal/force/force_device_opener.hpp"
#include "player/haptic/force_log.hpp"
#include "player/haptic/force_run_report.hpp"
#include "realtime/clock.hpp"
#include "storage/atomic_file.hpp"
#include "storage/number_text.hpp"
#include "storage/print_diagnostics.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg::force_app {
namespace {

void error(const std::string& message) { std::fprintf(stderr, "vimg-force: error: %s\n", message.c_str()); }

// A file written at the end must have a folder now, so that a typo fails before the device moves.
bool folder_exists_for(const std::string& file) {
  const std::filesystem::path parent = std::filesystem::path(file).parent_path();
  std::error_code ec;
  return parent.empty() || std::filesystem::is_directory(parent, ec);
}

}  // namespace

int run_force_session(const ForceArgs& args, const std::atomic<int>& signal_received) {
  VolumeSceneLoadOptions load_options;
  load_options.allow_files_outside_scene_folder = args.allow_outside_files;
  VolumeSceneLoadResult loaded = load_volume_scene_file(args.scene_path, load_options);
  print_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) return cmdline::kExitFailure;
  const DeviceProfile profile = loaded.loaded->scene.device;
  std::vector<Diagnostic> hand_problems;
  std::optional<std::vector<HandPathPoint>> hand = simulated_hand_path(args.path_file, hand_problems);
  print_diagnostics(hand_problems);
  if (!hand) return cmdline::kExitFailure;
  for (const std::string* file : {&args.log_file, &args.telemetry_file}) {
    if (!file->empty() && !folder_exists_for(*file)) {
      std::fprintf(stderr, "%s: error: cannot write there: the folder does not exist\n", file->c_str());
      return cmdline::kExitFailure;
    }
  }
  OpenedForceDevice opened =
      open_force_device(args.device, profile, std::move(*hand),
                        args.path_file.empty() ? "the hand at rest at the workspace centre" : "the hand on " + args.path_file);
  if (!opened.device) {
    error(opened.error);
    return cmdline::kExitFailure;
  }
  if (const int s = signal_received.load()) return exit_code_for_signal(s);  // nothing has moved yet

  HapticLoopConfig config = haptic_loop_config(profile, args.realtime_priority);
  // Two seconds of rows: the writer drains the ring every 5 ms.
  config.log_capacity_rows = args.log_file.empty() ? 0 : static_cast<std::size_t>(2.0 * profile.rate_hz);
  HapticLoop loop(*opened.device, config);
  loop.submit_scene(build_haptic_scene(*loaded.loaded));
  std::unique_ptr<ForceLogWriter> log;
  if (!args.log_file.empty()) {
    log = std::make_unique<ForceLogWriter>(loop, args.log_file);
    if (!log->ok()) {
      error(log->error());
      return cmdline::kExitFailure;
    }
    log->start();
  }
  if (!loop.start()) {
    error("cannot start the haptic loop at " + format_decimal(profile.rate_hz) + " Hz (100..4000)");
    return cmdline::kExitFailure;
  }
  const double start_s = monotonic_s();

  bool announced = false;
  TerminalStatusLine status;
  double next_status_s = 1.0;
  LoopWatch watch;
  if (args.seconds) watch.finished = [&] { return monotonic_s() - start_s >= *args.seconds; };
  watch.tick = [&](double elapsed_s) {
    if (!announced && loop.cycles() > 0) {
      announced = true;
      std::fprintf(stderr, "%s\n", loop_announcement(loop, opened.description).c_str());
    }
    if (elapsed_s >= next_status_s) {
      next_status_s += 1.0;
      status.show(format_status_line(loop.status()));
    }
  };
  const LoopRunEnd end = watch_loop(loop, signal_received, watch);  // the device is at rest when it returns
  status.finish();
  const std::string exit_reason = end.reason("seconds elapsed");
  int code = end.exit_code();

  if (log) {
    if (auto failure = log->finish()) {
      error(*failure);
      code = cmdline::kExitFailure;
    }
  }
  if (!args.telemetry_file.empty()) {
    const ForceRunReport report = make_force_run_report(loop, exit_reason, opened.description);
    if (auto failure = write_file_atomically(args.telemetry_file, force_run_report_json(report))) {
      error(*failure);
      code = cmdline::kExitFailure;
    }
  }
  if (loop.failed()) error("device fault: " + loop.fault_text());
  return code;
}

}  // namespace vimg::force_app
