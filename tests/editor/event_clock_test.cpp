#include "editor/core/event_clock.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

namespace vimg::editor {
namespace {

// A pointer that moves every 8 ms (server stamps in whole ms) whose events the GUI thread handles
// in bursts, once per frame of `frame_ms`: each event is placed at its true time plus the least
// handling delay seen so far (the pairing's only error, a constant between quick events), so the
// events of one burst keep their 8 ms spacing, whatever the clocks' offset and wherever the
// server count wraps.
void check_steady_pointer_through_bursts(std::uint32_t server_start_ms, double local_start_s, double frame_ms) {
  EventClock clock;
  const double period_s = 0.008;
  double least_delay_s = 1e9;
  double previous_s = -1e9;
  for (int k = 0; k < 200; ++k) {
    const double true_local_s = local_start_s + k * period_s;  // when the server took it in
    const std::uint32_t server_ms = server_start_ms + static_cast<std::uint32_t>(k * 8);
    // Handled at the end of the frame it arrived in (plus 0.2 ms to read it).
    const double frame_end_ms = (static_cast<int>(k * 8.0 / frame_ms) + 1) * frame_ms;
    const double handled_s = local_start_s + frame_end_ms * 1e-3 + 0.0002;
    least_delay_s = std::min(least_delay_s, handled_s - true_local_s);
    const double t = clock.map(server_ms, handled_s);
    EXPECT_LE(t, handled_s);
    EXPECT_NEAR(t, true_local_s + least_delay_s, 1e-6) << "event " << k;
    EXPECT_GE(t, previous_s - 1e-9) << "event " << k;
    previous_s = t;
  }
  EXPECT_LT(least_delay_s, 0.005);  // some event came late in its frame: the offset is tight
}

TEST(EventClock, SteadyPointerHandledInBurstsKeepsItsSteadyTimes) {
  check_steady_pointer_through_bursts(123456, 1000.0, 230.0);
  check_steady_pointer_through_bursts(5000, 42.5, 60.0);
}

TEST(EventClock, ServerCountWrapsWithoutAJump) {
  check_steady_pointer_through_bursts(0xFFFFFFFFu - 700, 7.0, 100.0);
}

TEST(EventClock, NeverLaterThanHandled) {
  EventClock clock;
  // A first event handled late, then one handled at once: the second sets the offset, the first
  // stays as it was mapped; a stamp out of order is still not placed after its handling.
  EXPECT_DOUBLE_EQ(clock.map(1000, 10.5), 10.5);
  EXPECT_NEAR(clock.map(1100, 10.5005), 10.5005, 1e-9);
  EXPECT_NEAR(clock.map(1200, 10.7), 10.6005, 1e-9);
  EXPECT_NEAR(clock.map(1150, 10.8), 10.5505, 1e-9);
  EXPECT_EQ(clock.events_seen(), 4u);
}

TEST(EventClock, AnOldQuickEventLeavesTheWindow) {
  // The server clock runs on after a pause of the window system: a quick event long ago no longer
  // sets the offset once the window has moved past it (no mapped time before its handling by more
  // than the queueing seen recently): the steady 5 ms delay sets it again.
  EventClock clock;
  clock.map(0, 0.0);  // offset 0
  // Afterwards every event is handled 5 ms after its stamp, shifted by +1 s of local time.
  double t = 0.0;
  for (std::size_t k = 1; k <= EventClock::kWindowEvents; ++k) {
    const std::uint32_t server_ms = static_cast<std::uint32_t>(k * 8);
    t = clock.map(server_ms, 1.0 + server_ms * 1e-3 + 0.005);
  }
  const double last_server_s = EventClock::kWindowEvents * 8 * 1e-3;
  EXPECT_NEAR(t, 1.005 + last_server_s, 1e-9);
}

}  // namespace
}  // namespace vimg::editor
