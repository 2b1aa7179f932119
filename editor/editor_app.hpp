#pragma once
// The vimg-editor application: one SDL window with Dear ImGui panels around a canvas at physical
// scale. The app wires the parts a designer works with and owns only the window, the event loop,
// the menu, the status bar and the dialogs:
//   DocumentSession (editor/core)  the document, undo, files, autosave and recovery
//   CanvasView                     the canvas, its view and the drawing tools
//   PropertiesPanel, ProblemList   the inspector
//   Playback                       playing mode, gesture recording and the oscilloscope
//   LibraryPanel                   the example and user images
//   CompareWindow                  the predicted confusion of images chosen in the library
//   ProposalWindow                 what to change so that people tell them apart (vimg separate)
//   AuditionWindow                 the saved document served to a phone or tablet on the LAN
// editor_app.cpp: window, loop and keys; app_frame.cpp: the frame, menu and status bar;
// app_dialogs.cpp: the dialogs and the file actions they lead to.
#include <SDL.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "editor/audition_window.hpp"
#include "editor/canvas_view.hpp"
#include "editor/compare_window.hpp"
#include "editor/core/document_session.hpp"
#include "editor/core/layout_log.hpp"
#include "editor/editor_options.hpp"
#include "editor/file_chooser.hpp"
#include "editor/library_panel.hpp"
#include "editor/notices.hpp"
#include "editor/playback.hpp"
#include "editor/problem_list.hpp"
#include "editor/properties_panel.hpp"
#include "editor/proposal_window.hpp"

namespace vimg::editor {

class EditorApp {
 public:
  explicit EditorApp(EditorOptions options);
  ~EditorApp();
  int run();  // the exit status

 private:
  // editor_app.cpp
  bool init_window();
  void shutdown_window();
  void dispatch(const SDL_Event& event);
  void handle_event(const SDL_Event& event);
  void handle_shortcut(const SDL_KeyboardEvent& key);
  void print_benchmark(std::vector<double>& frame_times_s) const;
  // app_frame.cpp
  void frame();
  void draw_menu_bar();
  void draw_status_bar(float w, float h);
  void update_title();
  void set_play_mode(bool on);
  // app_dialogs.cpp
  enum class PendingAction { none, new_document, open_file, import_file, quit };
  enum class PathPrompt { none, open, import_file, save_as, save_gesture };
  void request(PendingAction action, std::string path = {});  // asks to save first when dirty
  void perform(PendingAction action, const std::string& path);
  bool open_file(const std::string& path);
  bool import_file(const std::string& path);  // with import_options_
  bool save_to(const std::string& path, bool becomes_document_path);
  void save();  // to the current path, or asks for one
  void prompt_path(PathPrompt what, const std::string& initial);
  void draw_dialogs();
  void draw_recovery_dialog();
  void draw_unsaved_dialog();
  void draw_path_dialog();
  void path_chosen(const std::string& path);
  void import_chosen(const std::string& path);  // asks the import options, or opens a vibroimage PNG
  void draw_import_dialog();
  // app_proposal.cpp: the Proposed changes window's actions (open, apply, apply all, audition)
  // and what the player plays while a change is auditioned.
  void handle_proposal_action(const ProposalAction& action);
  void follow_document_or_audition();
  // The Mode menu's touch-latency choice, kept on this device (storage/touch_settings_file.hpp).
  void load_touch_settings();
  void save_touch_settings();

  EditorOptions options_;
  LayoutLog layout_;
  Notices notices_;
  DocumentSession session_;
  Playback playback_;
  CanvasView canvas_;
  PropertiesPanel properties_;
  ProblemList problems_;
  LibraryPanel library_;
  CompareWindow compare_;
  ProposalWindow proposal_;
  // While a proposed change is auditioned (auditioned_): the document with it made, what playing mode plays
  // instead of the document until playing stops or the document changes.
  std::optional<Image> auditioned_;
  std::uint64_t audition_of_change_ = 0;  // the document's change_count the audition was made from
  std::uint64_t audition_generation_ = 0;
  std::string audition_label_;
  AuditionWindow audition_{notices_};
  FileChooser chooser_;
  std::filesystem::path touch_settings_path_;

  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  bool quit_ = false;
  int frames_since_input_ = 0;  // frames drawn since the last event (idle when > kSettleFrames)
  std::vector<SDL_Scancode> keys_pressed_this_frame_;
  std::vector<Uint8> buttons_changed_this_frame_;
  std::vector<SDL_Event> held_events_;  // as of the last frame; input between frames reads it
  bool any_popup_open_ = false;
  std::string last_title_;

  // Dialogs
  PathPrompt path_prompt_ = PathPrompt::none;
  PendingAction pending_ = PendingAction::none;
  std::string pending_path_;
  bool unsaved_prompt_opening_ = false;
  bool recovery_prompt_opening_ = false;
  // File -> Import: the options asked before importing (picture width and levels; SVG scale).
  bool import_prompt_opening_ = false;
  bool import_picture_ = false;
  std::string import_path_;
  double import_width_mm_ = 100.0;
  int import_levels_ = 4;
  bool import_set_mm_per_unit_ = false;
  double import_mm_per_unit_ = 1.0;
  ImportOptions import_options_;
};

}  // namespace vimg::editor
