#pragma once
// Playing mode as the designer sees it: the Play button and the gesture recording controls, the
// mouse and touches turned into touch events for the PlaySession, the finger trail on the canvas
// and the oscilloscope of the drive beside the acceleration the chosen actuator is predicted to
// give. Owns the PlaySession (made on the first play) and the actuator the editor designs for
// (ActuatorFeel: `--actuator`, the Actuator choice, the weak-primitive marks on the canvas).
// GUI thread: the render thread only writes the drive into the DriveTap; the actuator model of the
// scope runs here, on the samples tapped since the last frame (PredictedScope).
#include <SDL.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/actuator_choice.hpp"
#include "editor/core/actuator_feel.hpp"
#include "editor/core/predicted_scope.hpp"
#include "editor/pointer_time.hpp"
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
  // Uses options.actuator when given (a bad profile is reported and the ideal one used), else the
  // profile chosen last time. recent_folders_store: the file chooser's recent folders (for "Open
  // profile..."); the chosen profile is remembered beside it (actuator_choice.hpp).
  Playback(const EditorOptions& options, Notices& notices, LayoutLog& layout,
           std::filesystem::path recent_folders_store);

  bool on() const { return on_; }
  // Starts playing `image` (true) or stops (false, writing the recorded gesture when
  // --record-gesture asked for it). A failure to start is reported and leaves drawing mode.
  void set_on(bool on, const Image& image);
  // What the output's device said since the last frame (a DRV2605L or HID fault, a device gone and
  // back) to stderr and the status bar (core/device_messages.hpp); every frame, and at a stop.
  void show_device_messages();
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
  // The oscilloscope panel below the canvas: the drive and the predicted acceleration side by side.
  void draw_scope(float x, float y, float w, float h);

  // The actuator the editor designs for, and its marks for the document as of `change_count`
  // (computed again only when the document or the profile changed).
  const ActuatorFeel& feel() const { return feel_; }
  void update_feel(const Image& image, std::uint64_t change_count) { feel_.marks(image, change_count); }
  // A dashed outline in the palette's warning colour around every primitive that is weak on the
  // actuator (as of the last update_feel); the canvas draws them into its cached picture (whose key
  // holds the feel's generation). More than 256 marks, or small ones, are drawn solid.
  void draw_feel_marks(ImDrawList* dl, const Viewport& view) const;

  bool can_save_gesture() const { return play_ && !play_->recorder().empty(); }
  bool recording() const { return play_ && play_->recording(); }
  void toggle_recording() {
    if (play_) play_->set_recording(!play_->recording());
  }
  bool has_session() const { return play_ != nullptr; }
  // Touch-latency compensation (from the command line; the Mode menu changes it): applies from the
  // next start of playing mode.
  TouchCompensation& touch() { return touch_; }
  std::optional<std::string> save_gesture(const std::string& path) const;

 private:
  const EditorOptions& options_;
  Notices& notices_;
  LayoutLog& layout_;
  std::unique_ptr<PlaySession> play_;
  bool on_ = false;
  TouchCompensation touch_;
  bool mouse_finger_down_ = false;
  PointerTime pointer_time_;  // each pointer event at its own time, not when handled
  std::uint64_t played_change_ = 0;
  std::vector<float> scope_samples_;
  std::vector<float> scope_acceleration_;
  ActuatorFeel feel_;
  ActuatorChoice choice_;
  PredictedScope predicted_;
};

}  // namespace vimg::editor
