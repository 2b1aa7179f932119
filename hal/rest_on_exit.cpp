#include "hal/rest_on_exit.hpp"

#include <atomic>

namespace vimg {

namespace {

std::atomic<int> g_rest_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal flag must be lock-free");

extern "C" void on_rest_signal(int signal_number) { g_rest_signal.store(signal_number); }

}  // namespace

bool rest_requested() noexcept { return g_rest_signal.load(std::memory_order_relaxed) != 0; }
int rest_signal() noexcept { return g_rest_signal.load(std::memory_order_relaxed); }
void request_rest(int signal_number) noexcept { g_rest_signal.store(signal_number); }
void clear_rest_request() noexcept { g_rest_signal.store(0); }

SignalRestScope::SignalRestScope() {
  struct sigaction action{};
  action.sa_handler = on_rest_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
}

SignalRestScope::~SignalRestScope() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

RestGuard::~RestGuard() {
  if (sink_ == nullptr) {
    return;
  }
  try {
    sink_->close();
  } catch (...) {
    // Nothing more can be done while unwinding; the driver already tried its retries.
  }
}

}  // namespace vimg
