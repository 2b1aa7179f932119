#include "apps/force/location_study.hpp"

#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "storage/print_diagnostics.hpp"
#include "storage/study/location_marks_file.hpp"
#include "apps/force/location_study_port.hpp"
#include "apps/force/location_study_trial.hpp"
#include "apps/force/loop_run.hpp"
#include "apps/force/status_line.hpp"
#include "cmdline/exit_codes.hpp"
#include "hal/force/force_device_opener.hpp"
#include "storage/number_text.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/trial_log.hpp"
#include "study/trial_plan.hpp"

namespace vimg::force_app {
namespace {

constexpr const char* kTrialFileSuffix = "location";
// Device faults in a row, without a mark in between, that end the study (docs/volume-location-study.md, "Location
// study"): a trial that faults this often will not go through on this device today.
constexpr int kMaxFaultsInARow = 3;

void error(const std::string& message) { std::fprintf(stderr, "vimg-force: error: %s\n", message.c_str()); }

// Enter on the terminal stands in for button 0 (for a device without buttons). Read without
// blocking from the control thread; only when stdin is a terminal (a pipe or a file would press by
// itself).
class EnterKey {
 public:
  explicit EnterKey(bool wanted) : enabled_(wanted && ::isatty(STDIN_FILENO) == 1) {}
  bool enabled() const { return enabled_; }
  // Whether a line has been entered since the last call.
  bool pressed() {
    bool line = false;
    pollfd in{STDIN_FILENO, POLLIN, 0};
    while (enabled_ && ::poll(&in, 1, 0) == 1 && (in.revents & (POLLIN | POLLHUP)) != 0) {
      char bytes[256];
      const ssize_t n = ::read(STDIN_FILENO, bytes, sizeof bytes);
      if (n <= 0) {
        enabled_ = false;  // end of input: no more key presses
        break;
      }
      if (std::memchr(bytes, '\n', static_cast<std::size_t>(n)) != nullptr) line = true;
    }
    return line;
  }

 private:
  bool enabled_;
};

// What the trials share: the arguments, the loop's settings, the keys, the status line.
struct StudyRun {
  const ForceArgs& args;
  const std::atomic<int>& signal_received;
  HapticLoopConfig config;
  std::string device_description;
  EnterKey keys;
  TerminalStatusLine status;
  bool announced = false;
};

struct Phase {
  bool started = false;
  LoopRunEnd end;
};

// One haptic loop on `port` with `scene`, from the start-up gate, until the port has a mark (or a
// signal, or a fault). `status_text` gives the status line from the port's clock.
Phase run_phase(StudyRun& run, MarkingPort& port, std::unique_ptr<HapticScene> scene,
                const std::function<std::string(double clock_s)>& status_text) {
  Phase phase;
  HapticLoop loop(port, run.config);
  loop.submit_scene(std::move(scene));
  run.keys.pressed();  // a key pressed before this phase does not count in it
  if (!loop.start()) {
    error("cannot start the haptic loop at " + format_decimal(run.config.rate_hz) + " Hz (100..4000)");
    return phase;
  }
  phase.started = true;
  double next_status_s = 0.0;
  LoopWatch watch;
  watch.finished = [&] { return port.marked(); };
  watch.tick = [&](double elapsed_s) {
    if (!run.announced && loop.cycles() > 0) {
      run.announced = true;
      std::fprintf(stderr, "%s\n", loop_announcement(loop, run.device_description).c_str());
    }
    if (run.keys.pressed()) port.press();
    if (status_text && elapsed_s >= next_status_s) {
      next_status_s = elapsed_s + 0.25;
      run.status.show(status_text(port.time_s()));
    }
  };
  phase.end = watch_loop(loop, run.signal_received, watch);  // zero force when it returns
  return phase;
}

// What a signal leaves: the device at rest, the trials done, where the next run begins.
int stopped_by_signal(int signal_number, const TrialLog& log) {
  std::fprintf(stderr, "vimg-force: %s: the device is at rest; %zu trials are in %s, the next run continues at trial %zu\n",
               signal_number == SIGTERM ? "SIGTERM" : "SIGINT", log.completed(), log.path().c_str(), log.completed() + 1);
  return exit_code_for_signal(signal_number);
}

// How a phase that did not end in a mark, nor in a fault (redo_after_fault), ends the program (the
// status line closed).
int stop_after(StudyRun& run, const Phase& phase, const TrialLog& log) {
  run.status.finish();
  if (!phase.started) return cmdline::kExitFailure;
  if (phase.end.why == LoopRunEnd::Why::signal) return stopped_by_signal(phase.end.signal_number, log);
  return phase.end.exit_code();
}

// A device fault ends the trial under way (wait or exploration) unrecorded, with the device at rest:
// the watch stopped the loop, zero force, before it returned. The trial then runs again from its
// start; the kMaxFaultsInARow-th fault in a row (no trial marked in between) ends the study instead.
// True: redo the trial.
bool redo_after_fault(StudyRun& run, const Phase& phase, std::size_t k, int& faults_in_a_row, const TrialLog& log) {
  run.status.finish();
  ++faults_in_a_row;
  if (faults_in_a_row < kMaxFaultsInARow) {
    std::fprintf(stderr, "vimg-force: device fault in trial %zu: redoing it (the device is at rest; fault %d in a row of at most %d): %s\n",
                 k, faults_in_a_row, kMaxFaultsInARow, phase.end.fault.c_str());
    return true;
  }
  std::fprintf(stderr,
               "vimg-force: error: device fault in trial %zu, %d in a row: the study stops with the device at rest; %zu trials are "
               "in %s, the next run continues at trial %zu: %s\n",
               k, faults_in_a_row, log.completed(), log.path().c_str(), log.completed() + 1, phase.end.fault.c_str());
  return false;
}

bool faulted(const Phase& phase) { return phase.started && phase.end.why == LoopRunEnd::Why::fault; }

}  // namespace

int run_location_study(const ForceArgs& args, const std::atomic<int>& signal_received) {
  const StudyFileResult<LocationStudy> loaded = load_location_study(args.study_file);
  print_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) return cmdline::kExitFailure;
  const std::vector<study::LocationTrialPlan> plan = study::plan_location_trials(*loaded.study, args.participant);
  const std::size_t total = plan.size();
  if (total == 0) {
    error(args.study_file + ": the study has no trials");
    return cmdline::kExitFailure;
  }

  // The simulated participant: the hand's path and the presses.
  std::vector<Diagnostic> hand_problems;
  const std::optional<std::vector<HandPathPoint>> hand = simulated_hand_path(args.path_file, hand_problems);
  print_diagnostics(hand_problems);
  if (!hand) return cmdline::kExitFailure;
  std::optional<std::vector<double>> press_times_s;
  if (!args.marks_file.empty()) {
    MarkTimesResult marks = load_mark_times(args.marks_file, total);
    print_diagnostics(marks.diagnostics);
    if (!marks.ok()) return cmdline::kExitFailure;
    press_times_s = std::move(marks.times_s);
  }
  StudyRun run{args, signal_received, {}, {}, EnterKey(!press_times_s), {}, false};
  if (args.is_sim() && !press_times_s && !run.keys.enabled()) {
    error("nobody can mark: with --device sim, give --marks M.csv (or run on a terminal and press Enter)");
    return cmdline::kExitUsage;
  }

  // The device: a real one is opened once, before anything is written.
  const DeviceProfile profile = location_study_device();
  run.config = haptic_loop_config(profile, args.realtime_priority);
  const std::string hand_description =
      args.path_file.empty() ? "the hand at rest at the workspace centre" : "the hand on " + args.path_file + " in every trial";
  OpenedForceDevice device;
  if (args.is_sim()) {
    run.device_description = "sim, " + hand_description;
  } else {
    device = open_force_device(args.device, profile, {}, {});
    if (!device.device) {
      error(device.error);
      return cmdline::kExitFailure;
    }
    run.device_description = device.description;
  }

  auto opened_log = TrialLog::open(args.results_dir, args.participant, kTrialFileSuffix, kLocationTrialHeader,
                                   TrialLogOptions{total, args.restart});
  if (auto* problems = std::get_if<std::vector<Diagnostic>>(&opened_log)) {
    print_diagnostics(*problems);
    return cmdline::kExitFailure;
  }
  TrialLog& log = std::get<TrialLog>(opened_log);
  print_diagnostics(log.warnings());
  const std::string total_text = std::to_string(total);
  if (log.completed() > 0) {
    std::fprintf(stderr, "vimg-force: participant %s continues at trial %zu of %zu (%zu done in %s)\n",
                 args.participant.c_str(), log.completed() + 1, total, log.completed(), log.path().c_str());
  } else {
    std::fprintf(stderr, "vimg-force: participant %s, %zu trials, into %s\n", args.participant.c_str(), total,
                 log.path().c_str());
  }
  if (!args.is_sim() || !press_times_s) {
    std::fprintf(stderr, "vimg-force: button 0 marks%s\n", run.keys.enabled() ? " (or Enter on this terminal)" : "");
  }

  int faults_in_a_row = 0;  // since the last mark: trial k's attempts that faulted
  for (std::size_t k = log.completed() + 1; k <= total;) {
    if (const int s = signal_received.load()) return stopped_by_signal(s, log);  // between trials: at rest
    const study::LocationTrialPlan& trial = plan[k - 1];
    const StudySet set = make_study_set(trial.data_seed);

    // 1. A real device rests (no scene: zero force, the soft wall still guards) until the participant
    //    presses; the simulated participant is always ready.
    OpenedForceDevice simulated;
    std::unique_ptr<MarkingPort> port;
    if (args.is_sim()) {
      simulated = open_force_device("sim", profile, *hand, hand_description);  // the hand at its path's start
      auto* sim = dynamic_cast<SimulatedForceDevice*>(simulated.device.get());
      if (!sim) {
        error(simulated.error.empty() ? "cannot make the simulated device" : simulated.error);
        return cmdline::kExitFailure;
      }
      if (k == args.sim_fault_trial && faults_in_a_row < args.sim_fault_count) sim->fail_read_at(kSimFaultTime_s);
      port = std::make_unique<MarkingPort>(*sim, run.config.rate_hz,
                                           press_times_s ? std::optional<double>((*press_times_s)[k - 1]) : std::nullopt);
    } else {
      run.status.settle("press button 0" + std::string(run.keys.enabled() ? " (or Enter)" : "") + " to begin trial " +
                        std::to_string(k) + " of " + total_text);
      MarkingPort ready(*device.device);
      const Phase wait = run_phase(run, ready, build_resting_scene(profile), {});
      if (faulted(wait)) {
        if (redo_after_fault(run, wait, k, faults_in_a_row, log)) continue;
        return cmdline::kExitFailure;
      }
      if (!wait.started || wait.end.why != LoopRunEnd::Why::finished) return stop_after(run, wait, log);
      port = std::make_unique<MarkingPort>(*device.device);
    }

    // 2. The trial: guidance plus the metaphor under test, until button 0 marks. (A log, not a
    //    terminal, gets the trial's first and last status as lines of their own.)
    if (!run.status.terminal()) std::fprintf(stderr, "%s\n", format_trial_status(k, total, trial.metaphor, 0.0).c_str());
    const Phase explore = run_phase(run, *port, build_location_trial_scene(set, trial.metaphor),
                                    [&](double clock_s) { return format_trial_status(k, total, trial.metaphor, clock_s); });
    if (!port->marked()) {
      if (!faulted(explore)) return stop_after(run, explore, log);
      if (redo_after_fault(run, explore, k, faults_in_a_row, log)) continue;
      return cmdline::kExitFailure;
    }

    // 3. The device is at rest; the row goes to disk, synced, before the next trial.
    const ProbeMark mark = port->mark();
    run.status.settle(format_trial_status(k, total, trial.metaphor, mark.time_s) + "  marked");
    LocationTrialInput input;
    input.participant = args.participant;
    input.trial = static_cast<int>(k);
    input.metaphor = trial.metaphor;
    input.seed = trial.data_seed;
    input.layout = set.layout;
    input.mark_m = mark.position_m;
    input.explore_s = mark.time_s;
    input.time_utc = utc_timestamp_now();
    if (auto failure = log.append(to_cells(location_trial_row(input)))) {
      error(log.path().string() + ": " + *failure);
      return cmdline::kExitFailure;
    }
    if (explore.end.why == LoopRunEnd::Why::signal) return stop_after(run, explore, log);  // marked as the signal came
    // Marked, so recorded, even if a fault came at the same check: the mark is the participant's.
    faults_in_a_row = 0;
    ++k;
  }
  std::fprintf(stderr, "vimg-force: participant %s has finished all %zu trials: %s\n", args.participant.c_str(), total,
               log.path().c_str());
  return cmdline::kExitOk;
}

}  // namespace vimg::force_app
