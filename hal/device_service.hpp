#pragma once
// The device service thread, run next to the renderer: all the fault handling that may allocate,
// throw, lock or wait, kept off the real-time thread.
//   - It drains each device's FaultLog (plain codes posted by the render thread) and formats the
//     messages with describe() for the status line and stderr (take_messages()).
//   - When a device's link is down (the render thread gave the device up), it reconnects it here:
//     the first attempt one reconnect interval after it saw the link go down, then again after
//     twice that, and so on up to max_reconnect_interval_s. reconnect() reopens and initializes the
//     device and puts the link up (release); the render thread sees it (acquire) and resumes. A
//     "reconnected" message follows the "device gone" one; a failed attempt is reported when its
//     reason changes.
//
// Threads: add(), start() and stop() from the control thread, add() only while stopped. The
// service thread (start()) calls poll(); a test may call poll() itself instead of start(), from one
// thread. take_messages() and reconnect_attempts() from any thread. The service never touches a
// device whose link is up.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "hal/serviced_device.hpp"

namespace vimg {

struct DeviceServiceOptions {
  double poll_interval_s = 0.02;
  double first_reconnect_interval_s = 0.5;
  double max_reconnect_interval_s = 8.0;
};

class DeviceService {
 public:
  // Messages kept for take_messages(); older ones are dropped when nobody takes them.
  static constexpr std::size_t kMaxMessages = 256;

  explicit DeviceService(DeviceServiceOptions options = {});
  ~DeviceService();  // stops
  DeviceService(const DeviceService&) = delete;
  DeviceService& operator=(const DeviceService&) = delete;

  void add(ServicedDevice& device);  // the device must outlive the service or its stop()

  // Starts the service thread; nothing happens if it runs already.
  void start();
  // Stops and joins it, then drains the fault logs once more (without reconnecting), so that the
  // last faults of a session are reported. Safe to call more than once.
  void stop();
  bool running() const { return thread_.joinable(); }

  // One service step at `now_ns` (monotonic): drain every fault log, then reconnect the devices
  // that are down and due.
  void poll(std::int64_t now_ns);

  // The messages formatted since the last call, oldest first.
  std::vector<std::string> take_messages();
  std::uint64_t reconnect_attempts() const { return attempts_.load(std::memory_order_relaxed); }

 private:
  struct Entry {
    ServicedDevice* device = nullptr;
    bool down = false;
    std::int64_t next_attempt_ns = 0;
    std::int64_t interval_ns = 0;
    std::string last_failure;
    std::uint64_t dropped_reported = 0;
  };
  void drain(Entry& entry);
  void reconnect_if_due(Entry& entry, bool down, std::int64_t now_ns);
  void post(std::string message);
  void run();

  DeviceServiceOptions options_;
  std::vector<Entry> entries_;
  std::thread thread_;
  std::mutex mutex_;  // guards stop_requested_ and messages_
  std::condition_variable wake_;
  bool stop_requested_ = false;
  std::vector<std::string> messages_;
  std::atomic<std::uint64_t> attempts_{0};
};

}  // namespace vimg
