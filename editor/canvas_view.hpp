#pragma once
// The canvas and its tools: the page at physical scale with rulers and grid, every primitive
// drawn by kind, the selection with its handles, and the mouse in drawing mode (place with the
// drawing tools, select, move, resize, box-select, pan, zoom, drop a library image). Owns the
// view (zoom, pan), the current tool, grid and snap, and the drag in progress. GUI thread.
#include <string>
#include <vector>

#include "editor/core/document_editor.hpp"
#include "editor/core/placement.hpp"
#include "editor/core/viewport.hpp"
#include "editor/notices.hpp"

struct ImDrawList;

namespace vimg::editor {

class LayoutLog;
class Playback;

// The drag-and-drop payload of a library image (its path) dropped on the canvas.
inline constexpr const char* kLibraryPayload = "VIMG_LIBRARY_FILE";

class CanvasView {
 public:
  CanvasView(DocumentEditor& doc, const Playback& playback, Notices& notices, LayoutLog& layout);

  // The display's density and the starting zoom (once the window exists).
  void set_density(double px_per_mm, double zoom);
  const Viewport& view() const { return view_; }

  // Draws the canvas window in the given region of the screen and handles the mouse on it.
  void draw(float x, float y, float w, float h);
  // The tool choice, grid and snap (in the tools panel).
  void draw_tool_choice(bool playing);

  // The canvas region on screen (px), as of the last frame.
  bool inside_px(float x, float y) const;

  // Keys of drawing mode without modifiers: tools, grid, snap, Enter closes a polygon, Esc
  // cancels it or clears the selection. True when the key was one of them.
  bool handle_key(int sdl_keycode);
  // View commands: actual size, zoom in and out about the canvas's centre.
  void actual_size();
  void zoom_by(double factor);
  bool& show_grid() { return show_grid_; }
  bool& snap() { return snap_; }
  // Ends a drag or a polygon in progress (leaving drawing mode).
  void cancel_interaction();

 private:
  static constexpr float kHandlePx = 5.0f;   // half the side of a handle's square
  static constexpr float kRulerPx = 22.0f;

  // canvas_view.cpp
  void draw_rulers(ImDrawList* dl, float x, float y, float w, float h) const;
  void draw_previews(ImDrawList* dl) const;
  // canvas_mouse.cpp
  void handle_mouse();
  void context_menu();
  void press(Point2Mm raw, Point2Mm mouse);
  void finish_polygon();
  void drop_library_file(const std::string& path, Point2Mm at);
  Point2Mm snapped(Point2Mm p) const;
  double snap_step_mm() const;
  // canvas_paint.cpp
  void draw_page(ImDrawList* dl) const;
  void draw_document(ImDrawList* dl, const std::vector<Element>& elements);
  void draw_element(ImDrawList* dl, const Element& element, bool highlighted);
  void draw_surface(ImDrawList* dl, const Surface& s, const RectMm& bounds, bool highlighted);
  void draw_line(ImDrawList* dl, const Line& l, bool highlighted) const;
  void draw_selection(ImDrawList* dl) const;

  DocumentEditor& doc_;
  const Playback& playback_;
  Notices& notices_;
  LayoutLog& layout_;
  Viewport view_;
  Tool tool_ = Tool::select;
  bool snap_ = true;
  bool show_grid_ = true;

  enum class Drag { none, placing, moving, resizing, box, panning };
  Drag drag_ = Drag::none;
  Point2Mm drag_start_mm_;
  Point2Mm drag_applied_mm_;  // the move applied so far in this drag
  RectMm resize_from_;
  int resize_handle_ = -1;    // 0..7 clockwise from top-left (core/placement.hpp)
  std::vector<Point2Mm> polygon_points_;
  std::vector<Point2Px> outline_px_, outline_lod_px_;  // scratch for drawing outlines, reused every frame
  std::vector<std::pair<double, double>> spans_;        // scratch for stripes
  float canvas_x_ = 0, canvas_y_ = 0, canvas_w_ = 0, canvas_h_ = 0;  // the canvas region, px
};

}  // namespace vimg::editor
