#pragma once
// The window system's time of an input event, mapped to the renderer's clock (monotonic_s()).
//
// A GUI thread busy drawing a frame handles the pointer events queued meanwhile all at once: stamped
// when handled, a steady pointer looks stop-and-go to the renderer. The X server stamps each event
// (a 32-bit millisecond count that wraps) when it takes it in; EventClock maps that stamp to the
// local clock by the pairing offset = min over recent events of (handled_s - server_s): an event is
// never handled before the server had it, and the least delayed of a recent window sets the
// offset (queueing delay only ever adds). The mapped time is never later than the handling time.
//
// Pure: no clock is read here; the caller passes both readings. Threads: one thread at a time.
#include <array>
#include <cstddef>
#include <cstdint>

namespace vimg::editor {

class EventClock {
 public:
  // Events whose offsets make up the minimum: some seconds of a moving pointer, so that a drifting
  // server clock is followed and one quick event sets the offset for the bursts after it.
  static constexpr std::size_t kWindowEvents = 512;

  // An event the server stamped `server_ms` that is handled now, at `handled_s` (local clock).
  // Returns its time on the local clock: server time + offset, never after handled_s.
  double map(std::uint32_t server_ms, double handled_s);
  std::size_t events_seen() const { return seen_; }

 private:
  std::array<double, kWindowEvents> offsets_s_{};
  std::size_t seen_ = 0;
  std::uint32_t last_server_ms_ = 0;
  std::int64_t unwrapped_ms_ = 0;
};

}  // namespace vimg::editor
