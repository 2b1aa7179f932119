#pragma once
// The renderer behind the page (docs/web.md): one compiled image (.vsc), rendered either offline
// for a gesture file, exactly as `vimg render IMAGE --gesture G --out F.csv [--actuator P]` does
// (player/offline_render.hpp, the drive through the actuator chain), or live, block by block, from
// pointer events (player/live_tracker.hpp and player/contact_mixer.hpp, as vimg-player does).
// No model, default or range lives here: they are all in the C++ the native tools use.
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "player/contact_mixer.hpp"
#include "player/live_tracker.hpp"
#include "player/scene.hpp"
#include "storage/vsc/vsc_image.hpp"

namespace vimg {

class WebRenderer {
 public:
  // Replaces the image (the live stream goes on with the new scene). False, with error(), when the
  // bytes are not a valid .vsc; the previous image stays.
  bool load_vsc(std::string_view bytes);
  bool loaded() const { return scene_ != nullptr; }
  const VscImage& image() const { return image_; }
  const Scene* scene() const { return scene_.get(); }

  // The drive of a gesture CSV at rate_hz from the render's first sample; false with error().
  bool render_gesture(std::string_view csv, double rate_hz);
  const std::vector<float>& rendered() const { return rendered_; }
  double rendered_start_s() const { return rendered_start_s_; }

  // Live: start at rate_hz (time 0), take events on the stream's clock, render the next frames.
  // live_event applies an event now (at the next sample, stamped with its own time). live_event_at
  // queues it: the next live_render applies the queued events in time order, each at the first
  // sample at or after its time_s, so events that arrive together (a block's worth, the coalesced
  // samples of one pointer event) keep their spacing. An event already past applies at the block's
  // first sample, stamped with its own time but never older than kOldestLiveEventS (the tracker drops
  // events older than its stale limit: an event must never be lost, a lift least of all). A full
  // queue, or a time that is not finite, applies the event at once.
  static constexpr double kOldestLiveEventS = 0.08;
  static constexpr std::size_t kMaxQueuedLiveEvents = 256;
  void live_start(double rate_hz);
  void live_event(const TouchEvent& event) { tracker_.apply(event, live_time_s_); }
  void live_event_at(const TouchEvent& event);
  std::size_t live_queued_events() const { return queued_; }
  // Touch-latency compensation (docs/latency.md): each finger predicted horizon_s ahead of the
  // sample's time (0: off). Kept across live_start().
  void live_set_prediction(double horizon_s) {
    live_horizon_s_ = horizon_s;
    tracker_.set_prediction(horizon_s);
  }
  double live_prediction_horizon_s() const { return tracker_.prediction_horizon_s(); }
  const std::vector<float>& live_render(std::size_t frames);
  double live_time_s() const { return live_time_s_; }
  std::size_t live_contacts() const { return mixer_.active_contacts(); }

  const std::string& error() const { return error_; }

 private:
  VscImage image_;
  std::shared_ptr<const Scene> scene_;
  std::vector<float> rendered_;
  double rendered_start_s_ = 0.0;
  ContactMixer mixer_;
  LiveTracker tracker_;
  double live_rate_hz_ = 48000.0;
  double live_time_s_ = 0.0;
  double live_horizon_s_ = 0.0;
  std::uint64_t live_samples_ = 0;
  std::vector<float> live_block_;
  std::array<TouchEvent, kMaxQueuedLiveEvents> queue_{};  // by time_s, ties in arrival order
  std::size_t queued_ = 0;
  void apply_live_event(TouchEvent event);
  std::string error_;
};

}  // namespace vimg
