#pragma once
// The vimg-editor application: one SDL window with Dear ImGui panels around a canvas at physical
// scale. Drawing mode edits the document through DocumentEditor; playing mode plays it through
// PlaySession. This file holds the state; editor_app.cpp the loop, files and dialogs,
// canvas.cpp the canvas, panels.cpp the side panels.
#include <SDL.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/core/document_editor.hpp"
#include "editor/core/recent_files.hpp"
#include "editor/core/recovery.hpp"
#include "editor/core/viewport.hpp"
#include "editor/editor_options.hpp"
#include "editor/play_session.hpp"
#include "storage/diagnostic.hpp"

struct ImDrawList;

namespace vimg::editor {

enum class Tool { select, dot, line, rect, ellipse, polygon };

class EditorApp {
 public:
  explicit EditorApp(EditorOptions options);
  ~EditorApp();
  int run();  // the exit status

 private:
  // --- editor_app.cpp: loop, input, files, dialogs
  bool init_window();
  void shutdown_window();
  void dispatch(const SDL_Event& event);
  void handle_event(const SDL_Event& event);
  void handle_shortcut(const SDL_KeyboardEvent& key);
  void handle_play_input(const SDL_Event& event);
  void frame();
  void draw_menu_bar();
  void draw_dialogs();
  void update_title();
  void autosave_if_due();
  void offer_recovery();

  enum class PendingAction { none, new_document, open_file, quit };
  void request(PendingAction action, std::string path = {});  // asks to save first when dirty
  void perform(PendingAction action, const std::string& path);
  bool open_file(const std::string& path);
  bool save_to(const std::string& path, bool becomes_document_path);
  void save();  // to the current path, or asks for one
  void set_play_mode(bool on);
  void report_error(std::string message);
  void print_layout(const char* name, float x, float y, float w, float h);

  // --- canvas.cpp
  void draw_canvas(float x, float y, float w, float h);
  void draw_document(ImDrawList* dl, const std::vector<Element>& elements, bool in_group);
  void draw_element(ImDrawList* dl, const Element& element, bool highlighted);
  void draw_rulers_and_grid(ImDrawList* dl, float x, float y, float w, float h);
  void draw_selection(ImDrawList* dl);
  void draw_play_overlay(ImDrawList* dl);
  void canvas_mouse_drawing_mode();
  void finish_placing(Point2Mm a, Point2Mm b);
  void finish_polygon();
  void drop_library_file(const std::string& path, Point2Mm at);
  Point2Mm snapped(Point2Mm p) const;
  double snap_step_mm() const;
  bool contacted(const Element& element) const;

  // --- panels.cpp
  void draw_tools_panel(float x, float y, float w, float h);
  void draw_properties_panel(float x, float y, float w, float h);
  void draw_element_properties(const std::string& id);
  void draw_document_properties();
  void draw_messages_panel(float x, float y, float w, float h);
  void draw_scope_panel(float x, float y, float w, float h);
  void refresh_validation();
  void refresh_library();
  // Wraps a property widget: one undo step per widget interaction.
  void track_widget_gesture();

  EditorOptions options_;
  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  bool quit_ = false;

  DocumentEditor doc_;
  std::string document_path_;  // empty for a new document
  RecentFiles recent_;
  RecoveryStore recovery_;
  Viewport view_;
  Tool tool_ = Tool::select;
  bool snap_ = true;
  bool show_grid_ = true;
  bool play_mode_ = false;
  std::unique_ptr<PlaySession> play_;

  // Canvas interaction
  enum class Drag { none, placing, moving, resizing, box, panning };
  Drag drag_ = Drag::none;
  Point2Mm drag_start_mm_;
  Point2Mm drag_applied_mm_;  // the move applied so far in this drag
  RectMm resize_from_;
  int resize_handle_ = -1;    // 0..7 clockwise from top-left
  std::vector<Point2Mm> polygon_points_;
  int frames_since_input_ = 0;  // frames drawn since the last event (idle when > kSettleFrames)
  std::vector<Point2Px> outline_px_, outline_lod_px_;  // scratch for drawing outlines, reused every frame
  float canvas_x_ = 0, canvas_y_ = 0, canvas_w_ = 0, canvas_h_ = 0;  // the canvas region, px
  bool canvas_placed_ = false;
  bool play_finger_down_ = false;

  // Panels
  std::vector<Diagnostic> diagnostics_;
  std::vector<Diagnostic> load_diagnostics_;
  std::uint64_t validated_change_ = ~0ull;
  double validation_due_s_ = 0.0;
  std::vector<std::filesystem::path> library_;
  std::vector<float> scope_samples_;

  // Autosave
  std::uint64_t autosaved_change_ = 0;
  double last_autosave_s_ = 0.0;

  // Dialogs
  enum class PathPrompt { none, open, save_as, save_gesture };
  PathPrompt path_prompt_ = PathPrompt::none;
  bool path_prompt_opening_ = false;
  int path_prompt_count_ = 0;
  char path_buffer_[1024] = {};
  PendingAction pending_ = PendingAction::none;
  std::string pending_path_;
  bool unsaved_prompt_opening_ = false;
  bool recovery_prompt_opening_ = false;
  bool recovery_prompt_active_ = false;
  bool any_popup_open_ = false;
  std::vector<SDL_Scancode> keys_pressed_this_frame_;
  std::vector<SDL_Event> held_events_;  // as of the last frame; input between frames reads it
  std::string error_message_;
  bool error_opening_ = false;
  std::string status_;
  std::string last_title_;
  std::vector<std::string> printed_layout_;
};

}  // namespace vimg::editor
