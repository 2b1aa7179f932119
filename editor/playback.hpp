#pragma once
// Playing mode as the designer sees it: the Play button and the gesture recording controls, the
// mouse and touches turned into touch events for the PlaySession, the finger trail on the canvas
// and the oscilloscope of the drive. Owns the PlaySession (made on the first play). GUI thread.
#include <SDL.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/core/viewport.hpp"
#include "editor/editor_options.hpp"
#include "editor/notices.hpp"
#include "editor/play_session.hpp"

struct ImDrawList;

namespace vimg::editor {

class CanvasView;
class LayoutLog;

class Playback {
 public:
  Playback(const EditorOptions& options, Notices& notices, LayoutLog& layout);

  bool on() const { return on_; }
  // Starts playing `image` (true) or stops (false, writing the recorded gesture when
  // --record-gesture asked for it). A failure to start is reported and leaves drawing mode.
  void set_on(bool on, const Image& image);
  // The document changed (change_count): play it from now on.
  void follow(const Image& image, std::uint64_t change_count);

  // Mouse (finger 0) and touches (fingers 1-9) on the canvas; ignored while a popup is open.
  void handle_input(const SDL_Event& event, const CanvasView& canvas, SDL_Window* window, bool popup_open);

  // Whether a finger touches the element (it is drawn highlighted).
  bool contacted(const Element& element) const;
  // The fading finger trail and the fingers.
  void draw_overlay(ImDrawList* dl, const Viewport& view) const;
  // The Play button and, while playing, the recording controls (in the tools panel). True when
  // the Play button was pressed (the app switches the mode).
  bool draw_controls();
  // The oscilloscope panel below the canvas.
  void draw_scope(float x, float y, float w, float h);

  bool can_save_gesture() const { return play_ && !play_->recorder().empty(); }
  bool recording() const { return play_ && play_->recording(); }
  void toggle_recording() {
    if (play_) play_->set_recording(!play_->recording());
  }
  bool has_session() const { return play_ != nullptr; }
  std::optional<std::string> save_gesture(const std::string& path) const;

 private:
  const EditorOptions& options_;
  Notices& notices_;
  LayoutLog& layout_;
  std::unique_ptr<PlaySession> play_;
  bool on_ = false;
  bool mouse_finger_down_ = false;
  std::uint64_t played_change_ = 0;
  std::vector<float> scope_samples_;
};

}  // namespace vimg::editor
