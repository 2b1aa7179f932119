#pragma once
// Who may use a device's bus right now: the render thread while the link is up, the device service
// thread while it is down. The render thread takes the link down when the device stops answering
// (after its last transfer); the service reconnects (reopen + initialize) and puts it up again
// (after its last transfer). The store is a release and the load an acquire, so whichever side
// sees the state also sees everything the other side did to the bus and to the driver's device
// state before handing it over: the two never touch the device at the same time.
//
// Threads: up() from any thread; take_down() only from the render thread while up, put_up() only
// from the service thread (or the control thread while neither runs) while down. Lock-free,
// allocation-free, never blocks.
#include <atomic>

namespace vimg {

class DeviceLink {
 public:
  bool up() const noexcept { return up_.load(std::memory_order_acquire); }
  void take_down() noexcept { up_.store(false, std::memory_order_release); }
  void put_up() noexcept { up_.store(true, std::memory_order_release); }

 private:
  std::atomic<bool> up_{true};
  static_assert(std::atomic<bool>::is_always_lock_free);
};

}  // namespace vimg
