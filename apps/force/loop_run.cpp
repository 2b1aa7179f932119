#include "apps/force/loop_run.hpp"

#include <csignal>

#include "cmdline/exit_codes.hpp"
#include "realtime/clock.hpp"
#include "storage/number_text.hpp"

namespace vimg::force_app {
namespace {

constexpr std::int64_t kPollPeriod_ns = 10'000'000;

}  // namespace

int exit_code_for_signal(int signal_number) {
  return signal_number == SIGTERM ? cmdline::kExitSigterm : cmdline::kExitSigint;
}

std::string LoopRunEnd::reason(const std::string& finished_reason) const {
  switch (why) {
    case Why::finished: return finished_reason;
    case Why::signal: return signal_number == SIGTERM ? "SIGTERM" : "SIGINT";
    case Why::fault: return "device fault: " + fault;
  }
  return finished_reason;
}

int LoopRunEnd::exit_code() const {
  switch (why) {
    case Why::finished: return cmdline::kExitOk;
    case Why::signal: return exit_code_for_signal(signal_number);
    case Why::fault: return cmdline::kExitFailure;
  }
  return cmdline::kExitFailure;
}

LoopRunEnd watch_loop(HapticLoop& loop, const std::atomic<int>& signal_received, const LoopWatch& watch) {
  LoopRunEnd end;
  const double start_s = monotonic_s();
  for (;;) {
    sleep_until_ns(monotonic_ns() + kPollPeriod_ns);
    if (const int s = signal_received.load()) {
      end.why = LoopRunEnd::Why::signal;
      end.signal_number = s;
      break;
    }
    if (!loop.running()) {
      end.why = LoopRunEnd::Why::fault;
      break;
    }
    if (watch.finished && watch.finished()) {
      end.why = LoopRunEnd::Why::finished;
      break;
    }
    if (watch.tick) watch.tick(monotonic_s() - start_s);
  }
  loop.stop();  // zero force before anything else
  if (end.why == LoopRunEnd::Why::fault) end.fault = loop.fault_text();
  return end;
}

std::string loop_announcement(const HapticLoop& loop, const std::string& device_description) {
  return "vimg-force: " + device_description + " at " + format_decimal(loop.rate_hz()) + " Hz, clamp " +
         format_decimal(loop.safety().clamp_N()) + " N, slew " + format_decimal(loop.safety().max_slew_N_per_ms()) +
         " N/ms, " + describe(loop.realtime_priority());
}

}  // namespace vimg::force_app
