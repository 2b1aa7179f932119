#pragma once
// Putting the actuator to rest first, however the program ends.
// - Normal exit and exceptions: RestGuard closes its sink in its destructor (stack unwinding).
// - SIGINT / SIGTERM: the handler installed by SignalRestScope only stores the signal number in a
//   lock-free atomic (async-signal-safe). Drivers check rest_requested() at the start of every
//   write() and put the actuator to rest at once; the app's loop sees it too and leaves normally,
//   so the RestGuards run before anything else is torn down.
#include <csignal>

#include "player/drive_sink.hpp"

namespace vimg {

bool rest_requested() noexcept;
int rest_signal() noexcept;          // the signal that asked, 0 if none
void request_rest(int signal_number) noexcept;  // what the handler does; also for tests
void clear_rest_request() noexcept;

// Installs the SIGINT/SIGTERM handlers; restores the previous ones when destroyed.
class SignalRestScope {
 public:
  SignalRestScope();
  ~SignalRestScope();
  SignalRestScope(const SignalRestScope&) = delete;
  SignalRestScope& operator=(const SignalRestScope&) = delete;

 private:
  struct sigaction previous_int_{};
  struct sigaction previous_term_{};
};

// Closes the sink (zero drive, standby) when the scope ends, for any reason. Never throws.
class RestGuard {
 public:
  explicit RestGuard(DriveSink& sink) : sink_(&sink) {}
  ~RestGuard();
  RestGuard(const RestGuard&) = delete;
  RestGuard& operator=(const RestGuard&) = delete;
  void release() { sink_ = nullptr; }  // the owner closed it already

 private:
  DriveSink* sink_;
};

}  // namespace vimg
