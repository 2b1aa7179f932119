#pragma once
// The editing model behind the editor's canvas: the document, the selection, the clipboard and
// unlimited undo/redo. Every edit is one undoable step; a continuous gesture (a drag, a slider)
// is bracketed by begin_gesture/end_gesture and becomes one step. No GUI code here.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "editor/core/document_problems.hpp"
#include "editor/core/geometry.hpp"
#include "primitives/image.hpp"

namespace vimg::editor {

class DocumentEditor {
 public:
  explicit DocumentEditor(Image image = Image{});

  // Replaces the document (new, open, recover): clears selection and history; not dirty.
  void reset(Image image);
  const Image& image() const { return image_; }

  // Selection: ids of top-level elements (a group is selected as a whole).
  const std::vector<std::string>& selection() const { return selection_; }
  bool is_selected(const std::string& id) const;
  void select_only(const std::string& id);
  void toggle_selected(const std::string& id);
  void clear_selection() { selection_.clear(); }
  void select_all();
  // Selects the elements whose bounds meet `rect`; adds to the selection when `add` is set.
  void select_in_rect(const RectMm& rect, bool add);
  // The topmost top-level element under the point, if any.
  std::optional<std::string> element_at(Point2Mm point, double tolerance_mm) const;
  std::optional<std::size_t> index_of(const std::string& id) const;
  const Element* find(const std::string& id) const;
  std::optional<RectMm> selection_bounds() const;

  // Edits. Each is one undoable step unless inside a gesture.
  std::string add_element(Element element);  // gives it a fresh id, selects it, returns the id
  void delete_selection();
  void duplicate_selection(double offset_mm);
  void copy_selection();
  void paste(double offset_mm);
  bool can_paste() const { return !clipboard_.empty(); }
  void move_selection(double dx_mm, double dy_mm);
  void resize_selection(const RectMm& from, const RectMm& to);
  void raise_selection();
  void lower_selection();
  void bring_selection_to_front();
  void send_selection_to_back();
  void group_selection();
  void ungroup_selection();
  void replace_element(const std::string& id, const Element& element);  // property edits
  void replace_image_settings(const Image& settings);  // size, meta, interaction; not children
  // The children of `image` (the document with a proposed change of `vimg separate` made: the same
  // elements, other tactile values): one undoable step; nothing when they are the same.
  void replace_tactile_values(const Image& image);
  // Clamps each value the fixes name into its range (storage/parameter_table.hpp), as it is now:
  // one undoable step for all of them. Returns how many values changed (0: no step).
  std::size_t clamp_values(const std::vector<ClampFix>& fixes);

  // A gesture collects the edits made until end_gesture into one undo step (none if nothing changed).
  void begin_gesture();
  void end_gesture();
  bool in_gesture() const { return gesture_start_.has_value(); }

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  void undo();
  void redo();
  std::size_t undo_depth() const { return undo_.size(); }

  bool dirty() const { return revision_ != saved_revision_; }
  void mark_saved() { saved_revision_ = revision_; }
  // The document differs from its file (e.g. recovered after a crash).
  void mark_unsaved() { saved_revision_ = 0; }
  // Increases on every change of the document, including undo and redo.
  std::uint64_t change_count() const { return change_count_; }

 private:
  struct State {
    Image image;
    std::vector<std::string> selection;
    std::uint64_t revision = 0;
  };
  // Records the current state for undo (outside gestures) and gives the coming change a revision.
  void before_change();
  void after_change();
  State current_state() const;
  void restore(State state);
  std::vector<std::size_t> selected_indices() const;  // ascending paint order

  Image image_;
  std::vector<std::string> selection_;
  std::vector<Element> clipboard_;
  int paste_count_ = 0;
  std::vector<State> undo_;
  std::vector<State> redo_;
  std::optional<State> gesture_start_;
  bool gesture_changed_ = false;
  std::uint64_t revision_ = 0;
  std::uint64_t next_revision_ = 1;
  std::uint64_t saved_revision_ = 0;
  std::uint64_t change_count_ = 0;
};

}  // namespace vimg::editor
