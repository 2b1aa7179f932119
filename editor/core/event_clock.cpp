#include "editor/core/event_clock.hpp"

#include <algorithm>

namespace vimg::editor {

double EventClock::map(std::uint32_t server_ms, double handled_s) {
  // Unwrap the 32-bit count (it wraps every 49.7 days): the signed step from the last event.
  if (seen_ == 0) {
    unwrapped_ms_ = server_ms;
  } else {
    unwrapped_ms_ += static_cast<std::int32_t>(server_ms - last_server_ms_);
  }
  last_server_ms_ = server_ms;
  const double server_s = static_cast<double>(unwrapped_ms_) * 1e-3;
  offsets_s_[seen_ % kWindowEvents] = handled_s - server_s;
  ++seen_;
  const std::size_t n = std::min(seen_, kWindowEvents);
  const double offset_s = *std::min_element(offsets_s_.begin(), offsets_s_.begin() + static_cast<std::ptrdiff_t>(n));
  return std::min(server_s + offset_s, handled_s);
}

}  // namespace vimg::editor
