// vimg-force: feel a volume scene with a force device (docs/volume-force-device.md, "Feel it with a force
// device"), or run the volume paper's location study on it ("Location study").
//   vimg-force SCENE --device sim|hid[:PATH] [--path P.csv] [--seconds S] [--log F.csv]
//              [--telemetry T.json] [--realtime-priority N]
//   vimg-force --study LSTUDY.xml --participant ID --results DIR --device sim|hid[:PATH]
//              [--restart] [--path P.csv --marks M.csv] [--realtime-priority N]
// Headless: the haptic loop runs on its own real-time thread; this thread waits for the end (the
// time, a mark, a signal or a fault), then stops the loop (zero force first), completes its files,
// and exits 0, 130 (SIGINT), 143 (SIGTERM), 1 (fault or bad input) or 2 (usage).
#include <atomic>
#include <csignal>

#include "apps/force/force_args.hpp"
#include "apps/force/force_session.hpp"
#include "apps/force/location_study.hpp"

namespace {

std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

// Async-signal-safe: only a lock-free atomic store.
extern "C" void on_signal(int signal_number) { g_signal.store(signal_number); }

void catch_signals() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  const auto parsed = vimg::force_app::parse_force_args(argc, argv);
  if (!parsed.args) return parsed.exit_code;
  catch_signals();
  if (parsed.args->is_study()) return vimg::force_app::run_location_study(*parsed.args, g_signal);
  return vimg::force_app::run_force_session(*parsed.args, g_signal);
}
