#include "web/server/event_stream.hpp"

#include <algorithm>

namespace vimg::web {

std::string format_event_message(std::string_view event, std::string_view data) {
  std::string message = "event: " + std::string(event) + "\n";
  std::size_t start = 0;
  while (true) {
    const std::size_t end = data.find_first_of("\r\n", start);
    message += "data: " + std::string(data.substr(start, end == std::string_view::npos ? end : end - start)) + "\n";
    if (end == std::string_view::npos) break;
    start = end + 1;
    if (data[end] == '\r' && start < data.size() && data[start] == '\n') ++start;
  }
  return message + "\n";
}

void EventBroadcaster::publish(std::string message) {
  {
    const std::lock_guard lock(mutex_);
    if (closed_) return;
    kept_.push_back(std::move(message));
    if (kept_.size() > kKeptEventMessages) kept_.pop_front();
    ++published_;
  }
  changed_.notify_all();
}

std::int64_t EventBroadcaster::open_stream(std::optional<std::int64_t> last_event_id) {
  const std::lock_guard lock(mutex_);
  if (closed_ || open_streams_ >= kMaxEventStreams) return -1;
  ++open_streams_;
  if (last_event_id && *last_event_id >= 0 && *last_event_id <= published_) return *last_event_id;
  return published_;
}

void EventBroadcaster::close_stream() {
  const std::lock_guard lock(mutex_);
  open_streams_ = std::max(0, open_streams_ - 1);
}

EventBroadcaster::Wait EventBroadcaster::wait_after(std::int64_t& cursor, std::chrono::milliseconds max_wait) {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, max_wait, [&] { return closed_ || published_ > cursor; });
  Wait wait;
  if (closed_) {
    wait.closed = true;
    return wait;
  }
  const std::int64_t oldest_kept = published_ - static_cast<std::int64_t>(kept_.size());
  for (std::int64_t n = std::max(cursor, oldest_kept); n < published_; ++n) {
    wait.text += "id: " + std::to_string(n + 1) + "\n" + kept_[static_cast<std::size_t>(n - oldest_kept)];
  }
  cursor = published_;
  return wait;
}

void EventBroadcaster::close() {
  {
    const std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

int EventBroadcaster::open_streams() const {
  const std::lock_guard lock(mutex_);
  return open_streams_;
}

}  // namespace vimg::web
