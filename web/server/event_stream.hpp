#pragma once
// Server-Sent Events for the open pages (docs/web-serving.md, "Serving"): `/events` streams
// "event: image\ndata: NAME\n\n" each time an image of the site was rewritten, so the page fetches
// images/NAME.vsc again. One EventBroadcaster is shared by every open stream: publish() appends a
// message and wakes them all; each stream keeps a cursor (the number of messages it has sent) and
// waits for the ones after it. Each message goes out with its number ("id: N", counting from 1), so
// a page whose stream ended (its lifetime, a lost network) reopens it with Last-Event-ID: N and
// gets what it missed. Only the last kKeptEventMessages are kept: a stream that fell further
// behind gets those (the page reloads the same images either way).
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

namespace vimg::web {

inline constexpr std::size_t kKeptEventMessages = 256;
// How often an idle stream sends a comment, so that a page that has gone is noticed.
inline constexpr std::chrono::seconds kEventKeepAlive{15};
// At most this many pages listen at once; a further /events gets only a retry hint
// (kEventStreamFullRetry) and its page tries again then.
inline constexpr int kMaxEventStreams = 8;

// "event: EVENT\ndata: LINE\n...\n\n": every line of `data` in a data field of its own, as the
// SSE format requires (a page joins them again with "\n"); a CR or CRLF counts as a line break.
std::string format_event_message(std::string_view event, std::string_view data);

class EventBroadcaster {
 public:
  // Adds a message (formatted) and wakes every waiting stream. Nothing once closed.
  void publish(std::string message);

  // Opens one more stream if fewer than kMaxEventStreams are open; returns its cursor (every
  // message published after this call reaches it, or after message `last_event_id` when that is
  // one this broadcaster has published), or -1 when full or closed.
  std::int64_t open_stream(std::optional<std::int64_t> last_event_id = std::nullopt);
  void close_stream();

  struct Wait {
    std::string text;     // the messages after the cursor with their ids, concatenated; empty after a timeout
    bool closed = false;  // the broadcaster was closed: the stream must end
  };
  // Blocks until a message after `cursor` exists (returns them all and moves the cursor), the
  // broadcaster closes, or `max_wait` passes (a keep-alive comment is then due).
  Wait wait_after(std::int64_t& cursor, std::chrono::milliseconds max_wait);

  // Wakes every stream for the last time: they end, and no stream opens any more.
  void close();

  int open_streams() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::string> kept_;  // the last messages; kept_.back() is message number published_ - 1
  std::int64_t published_ = 0;
  int open_streams_ = 0;
  bool closed_ = false;
};

}  // namespace vimg::web
