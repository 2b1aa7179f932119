#pragma once
// The canvas and its tools: the page at physical scale with rulers and grid, every primitive
// drawn by kind, the selection with its handles, and the mouse in drawing mode (place with the
// drawing tools, select, move, resize, box-select, pan, zoom, drop a library image). Owns the
// view (zoom, pan), the current tool, grid and snap, and the drag in progress. GUI thread.
#include <SDL.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/core/document_editor.hpp"
#include "editor/core/placement.hpp"
#include "editor/core/viewport.hpp"
#include "editor/notices.hpp"

struct ImDrawList;

namespace vimg::editor {

class CanvasCache;
class LayoutLog;
class Playback;

// The drag-and-drop payload of a library image (its path) dropped on the canvas.
inline constexpr const char* kLibraryPayload = "VIMG_LIBRARY_FILE";

class CanvasView {
 public:
  CanvasView(DocumentEditor& doc, const Playback& playback, Notices& notices, LayoutLog& layout);

  ~CanvasView();
  // The display's density and the starting zoom, and the renderer the cached picture is drawn
  // with (once the window exists; null: no cache).
  void set_density(double px_per_mm, double zoom);
  void set_renderer(SDL_Renderer* renderer);
  // How often the cached picture was drawn (canvas_cache.hpp).
  std::uint64_t cache_builds() const;
  // The renderer lost its textures' pixels: the cached picture is drawn again.
  void picture_lost();
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
  // Delete with a vertex of the selected polygon chosen: removes that vertex (one undo step) and
  // returns true; a polygon keeps 3 vertices and a line both ends (true, with a status line).
  // False when no vertex is chosen (Delete then removes the selection).
  bool delete_chosen_vertex();

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
  // The single selected element whose points can be dragged (select tool, drawing mode), if any.
  const Element* vertex_target() const;
  bool press_vertex(Point2Mm raw);
  void drag_vertex(Point2Mm mouse);
  Point2Mm snapped(Point2Mm p) const;
  double snap_step_mm() const;
  // canvas_paint.cpp
  void draw_picture(ImDrawList* dl);
  void draw_page(ImDrawList* dl) const;
  // Draws the elements except the top-level ones named in `left_out`.
  void draw_document(ImDrawList* dl, const std::vector<Element>& elements,
                     const std::vector<std::string>& left_out = {});
  void draw_element(ImDrawList* dl, const Element& element, bool highlighted);
  void draw_surface(ImDrawList* dl, const Surface& s, const RectMm& bounds, bool highlighted);
  void draw_line(ImDrawList* dl, const Line& l, bool highlighted) const;
  void draw_selection(ImDrawList* dl) const;
  void draw_vertex_handles(ImDrawList* dl) const;

  DocumentEditor& doc_;
  const Playback& playback_;
  Notices& notices_;
  LayoutLog& layout_;
  Viewport view_;
  Tool tool_ = Tool::select;
  bool snap_ = true;
  bool show_grid_ = true;

  enum class Drag { none, placing, moving, resizing, box, panning, vertex };
  Drag drag_ = Drag::none;
  Point2Mm drag_start_mm_;
  Point2Mm drag_applied_mm_;  // the move applied so far in this drag
  RectMm resize_from_;
  int resize_handle_ = -1;    // 0..7 clockwise from top-left (core/placement.hpp)
  std::vector<Point2Mm> polygon_points_;
  std::string vertex_owner_;                 // the element whose vertex is chosen
  std::optional<std::size_t> vertex_index_;  // the chosen (and dragged) vertex
  std::vector<Point2Px> outline_px_, outline_lod_px_;  // scratch for drawing outlines, reused every frame
  std::vector<std::pair<double, double>> spans_;        // scratch for stripes
  std::unique_ptr<CanvasCache> cache_;
  std::uint64_t drag_base_change_ = 0;  // the document's change_count when the drag began
  float canvas_x_ = 0, canvas_y_ = 0, canvas_w_ = 0, canvas_h_ = 0;  // the canvas region, px
};

}  // namespace vimg::editor
