#include "hal/device_service.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

#include "realtime/clock.hpp"

namespace vimg {

namespace {
std::int64_t to_ns(double seconds) { return std::llround(seconds * 1e9); }
}  // namespace

DeviceService::DeviceService(DeviceServiceOptions options) : options_(options) {}

DeviceService::~DeviceService() { stop(); }

void DeviceService::add(ServicedDevice& device) {
  Entry entry;
  entry.device = &device;
  entry.dropped_reported = device.faults().dropped();
  entries_.push_back(std::move(entry));
}

void DeviceService::start() {
  if (thread_.joinable()) return;
  {
    const std::lock_guard lock(mutex_);
    stop_requested_ = false;
  }
  thread_ = std::thread([this] { run(); });
}

void DeviceService::stop() {
  if (!thread_.joinable()) return;
  {
    const std::lock_guard lock(mutex_);
    stop_requested_ = true;
  }
  wake_.notify_all();
  thread_.join();
  for (auto& entry : entries_) drain(entry);
}

void DeviceService::run() {
  const auto period = std::chrono::nanoseconds(to_ns(options_.poll_interval_s));
  std::unique_lock lock(mutex_);
  while (!stop_requested_) {
    lock.unlock();
    poll(monotonic_ns());
    lock.lock();
    wake_.wait_for(lock, period, [this] { return stop_requested_; });
  }
}

void DeviceService::poll(std::int64_t now_ns) {
  for (auto& entry : entries_) {
    // Read the link before draining: the render thread posts "device gone" before it takes the
    // link down, so that event is drained here, before any reconnection of this step.
    const bool down = !entry.device->link().up();
    drain(entry);
    reconnect_if_due(entry, down, now_ns);
  }
}

void DeviceService::drain(Entry& entry) {
  FaultLog& log = entry.device->faults();
  while (const auto event = log.pop()) post(describe(*event, entry.device->device_path()));
  const std::uint64_t dropped = log.dropped();
  if (dropped != entry.dropped_reported) {
    post(entry.device->device_path() + ": " + std::to_string(dropped - entry.dropped_reported) +
         " fault events lost (the fault log was full)");
    entry.dropped_reported = dropped;
  }
}

void DeviceService::reconnect_if_due(Entry& entry, bool down, std::int64_t now_ns) {
  if (!down) {
    entry.down = false;
    return;
  }
  if (!entry.down) {  // newly down: the first attempt after one interval
    entry.down = true;
    entry.interval_ns = to_ns(options_.first_reconnect_interval_s);
    entry.next_attempt_ns = now_ns + entry.interval_ns;
    entry.last_failure.clear();
    return;
  }
  if (now_ns < entry.next_attempt_ns) return;
  attempts_.fetch_add(1, std::memory_order_relaxed);
  try {
    entry.device->reconnect();
    entry.down = false;
    post(describe(FaultEvent{FaultKind::reconnected, 0, now_ns / 1000}, entry.device->device_path()));
  } catch (const std::exception& error) {
    if (entry.last_failure != error.what()) {
      entry.last_failure = error.what();
      post(entry.last_failure + "; will try to reconnect again");
    }
    entry.interval_ns = std::min(2 * entry.interval_ns, to_ns(options_.max_reconnect_interval_s));
    entry.next_attempt_ns = now_ns + entry.interval_ns;
  }
}

void DeviceService::post(std::string message) {
  const std::lock_guard lock(mutex_);
  if (messages_.size() == kMaxMessages) messages_.erase(messages_.begin());
  messages_.push_back(std::move(message));
}

std::vector<std::string> DeviceService::take_messages() {
  const std::lock_guard lock(mutex_);
  std::vector<std::string> taken;
  taken.swap(messages_);
  return taken;
}

}  // namespace vimg
