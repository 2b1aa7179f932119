#include "editor/core/document_editor.hpp"

#include <algorithm>

#include "editor/core/element_ids.hpp"

namespace vimg::editor {

DocumentEditor::DocumentEditor(Image image) { reset(std::move(image)); }

void DocumentEditor::reset(Image image) {
  assign_missing_ids(image);
  image_ = std::move(image);
  selection_.clear();
  undo_.clear();
  redo_.clear();
  gesture_start_.reset();
  gesture_changed_ = false;
  paste_count_ = 0;
  revision_ = next_revision_++;
  saved_revision_ = revision_;
  ++change_count_;
}

bool DocumentEditor::is_selected(const std::string& id) const {
  return std::find(selection_.begin(), selection_.end(), id) != selection_.end();
}

void DocumentEditor::select_only(const std::string& id) { selection_ = {id}; }

void DocumentEditor::toggle_selected(const std::string& id) {
  auto it = std::find(selection_.begin(), selection_.end(), id);
  if (it != selection_.end()) {
    selection_.erase(it);
  } else {
    selection_.push_back(id);
  }
}

void DocumentEditor::select_all() {
  selection_.clear();
  for (const Element& e : image_.children) {
    if (!e.id.empty()) selection_.push_back(e.id);
  }
}

void DocumentEditor::select_in_rect(const RectMm& rect, bool add) {
  if (!add) selection_.clear();
  for (const Element& e : image_.children) {
    if (e.id.empty() || is_selected(e.id)) continue;
    if (auto b = element_bounds(e); b && b->intersects(rect)) selection_.push_back(e.id);
  }
}

std::optional<std::string> DocumentEditor::element_at(Point2Mm point, double tolerance_mm) const {
  for (auto it = image_.children.rbegin(); it != image_.children.rend(); ++it) {
    if (!it->id.empty() && element_contains(*it, point, tolerance_mm)) return it->id;
  }
  return std::nullopt;
}

std::optional<std::size_t> DocumentEditor::index_of(const std::string& id) const {
  for (std::size_t i = 0; i < image_.children.size(); ++i) {
    if (image_.children[i].id == id) return i;
  }
  return std::nullopt;
}

const Element* DocumentEditor::find(const std::string& id) const {
  auto i = index_of(id);
  return i ? &image_.children[*i] : nullptr;
}

std::optional<RectMm> DocumentEditor::selection_bounds() const {
  std::optional<RectMm> r;
  for (std::size_t i : selected_indices()) {
    if (auto b = element_bounds(image_.children[i])) r = r ? united(*r, *b) : *b;
  }
  return r;
}

std::vector<std::size_t> DocumentEditor::selected_indices() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < image_.children.size(); ++i) {
    if (!image_.children[i].id.empty() && is_selected(image_.children[i].id)) out.push_back(i);
  }
  return out;
}

DocumentEditor::State DocumentEditor::current_state() const { return State{image_, selection_, revision_}; }

void DocumentEditor::before_change() {
  if (gesture_start_) {
    gesture_changed_ = true;
  } else {
    undo_.push_back(current_state());
    redo_.clear();
  }
}

void DocumentEditor::after_change() {
  revision_ = next_revision_++;
  ++change_count_;
}

void DocumentEditor::restore(State state) {
  image_ = std::move(state.image);
  selection_ = std::move(state.selection);
  revision_ = state.revision;
  ++change_count_;
}

std::string DocumentEditor::add_element(Element element) {
  before_change();
  std::set<std::string> used = collect_ids(image_);
  renew_ids(element, used);
  std::string id = element.id;
  image_.children.push_back(std::move(element));
  selection_ = {id};
  after_change();
  return id;
}

void DocumentEditor::delete_selection() {
  const auto indices = selected_indices();
  if (indices.empty()) return;
  before_change();
  for (auto it = indices.rbegin(); it != indices.rend(); ++it) {
    image_.children.erase(image_.children.begin() + static_cast<std::ptrdiff_t>(*it));
  }
  selection_.clear();
  after_change();
}

void DocumentEditor::duplicate_selection(double offset_mm) {
  const auto indices = selected_indices();
  if (indices.empty()) return;
  before_change();
  std::set<std::string> used = collect_ids(image_);
  std::vector<std::string> copies;
  for (std::size_t i : indices) {
    Element copy = image_.children[i];
    renew_ids(copy, used);
    translate_element(copy, offset_mm, offset_mm);
    copies.push_back(copy.id);
    image_.children.push_back(std::move(copy));
  }
  selection_ = copies;
  after_change();
}

void DocumentEditor::copy_selection() {
  const auto indices = selected_indices();
  if (indices.empty()) return;
  clipboard_.clear();
  for (std::size_t i : indices) clipboard_.push_back(image_.children[i]);
  paste_count_ = 0;
}

void DocumentEditor::paste(double offset_mm) {
  if (clipboard_.empty()) return;
  before_change();
  ++paste_count_;
  std::set<std::string> used = collect_ids(image_);
  std::vector<std::string> pasted;
  for (Element copy : clipboard_) {
    renew_ids(copy, used);
    translate_element(copy, offset_mm * paste_count_, offset_mm * paste_count_);
    pasted.push_back(copy.id);
    image_.children.push_back(std::move(copy));
  }
  selection_ = pasted;
  after_change();
}

void DocumentEditor::move_selection(double dx_mm, double dy_mm) {
  const auto indices = selected_indices();
  if (indices.empty() || (dx_mm == 0.0 && dy_mm == 0.0)) return;
  before_change();
  for (std::size_t i : indices) translate_element(image_.children[i], dx_mm, dy_mm);
  after_change();
}

void DocumentEditor::resize_selection(const RectMm& from, const RectMm& to) {
  const auto indices = selected_indices();
  if (indices.empty() || from == to) return;
  before_change();
  for (std::size_t i : indices) map_element(image_.children[i], from, to);
  after_change();
}

void DocumentEditor::raise_selection() {
  auto& c = image_.children;
  bool changed = false;
  for (std::size_t i = c.size(); i-- > 1;) {
    if (is_selected(c[i - 1].id) && !is_selected(c[i].id)) {
      if (!changed) before_change();
      changed = true;
      std::swap(c[i - 1], c[i]);
    }
  }
  if (changed) after_change();
}

void DocumentEditor::lower_selection() {
  auto& c = image_.children;
  bool changed = false;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    if (is_selected(c[i + 1].id) && !is_selected(c[i].id)) {
      if (!changed) before_change();
      changed = true;
      std::swap(c[i], c[i + 1]);
    }
  }
  if (changed) after_change();
}

void DocumentEditor::bring_selection_to_front() {
  if (selected_indices().empty()) return;
  before_change();
  std::stable_partition(image_.children.begin(), image_.children.end(),
                        [&](const Element& e) { return e.id.empty() || !is_selected(e.id); });
  after_change();
}

void DocumentEditor::send_selection_to_back() {
  if (selected_indices().empty()) return;
  before_change();
  std::stable_partition(image_.children.begin(), image_.children.end(),
                        [&](const Element& e) { return !e.id.empty() && is_selected(e.id); });
  after_change();
}

void DocumentEditor::group_selection() {
  const auto indices = selected_indices();
  if (indices.empty()) return;
  before_change();
  std::set<std::string> used = collect_ids(image_);
  Element group;
  group.id = fresh_id("group", used);
  Group body;
  body.name = group.id;
  for (std::size_t i : indices) body.children.push_back(image_.children[i]);
  group.body = std::move(body);
  // The group takes the place of the topmost member in paint order.
  const std::size_t insert_at = indices.back() + 1 - indices.size();
  for (auto it = indices.rbegin(); it != indices.rend(); ++it) {
    image_.children.erase(image_.children.begin() + static_cast<std::ptrdiff_t>(*it));
  }
  const std::string id = group.id;
  image_.children.insert(image_.children.begin() + static_cast<std::ptrdiff_t>(insert_at), std::move(group));
  selection_ = {id};
  after_change();
}

void DocumentEditor::ungroup_selection() {
  const auto indices = selected_indices();
  bool any_group = std::any_of(indices.begin(), indices.end(),
                               [&](std::size_t i) { return std::holds_alternative<Group>(image_.children[i].body); });
  if (!any_group) return;
  before_change();
  std::vector<Element> out;
  std::vector<std::string> new_selection;
  for (Element& e : image_.children) {
    if (auto* g = std::get_if<Group>(&e.body); g && !e.id.empty() && is_selected(e.id)) {
      for (Element& c : g->children) {
        if (!c.id.empty()) new_selection.push_back(c.id);
        out.push_back(std::move(c));
      }
    } else {
      if (!e.id.empty() && is_selected(e.id)) new_selection.push_back(e.id);
      out.push_back(std::move(e));
    }
  }
  image_.children = std::move(out);
  selection_ = std::move(new_selection);
  after_change();
}

void DocumentEditor::replace_element(const std::string& id, const Element& element) {
  auto i = index_of(id);
  if (!i || image_.children[*i] == element) return;
  before_change();
  image_.children[*i] = element;
  if (element.id != id) {
    std::replace(selection_.begin(), selection_.end(), id, element.id);
  }
  after_change();
}

namespace {

Element* find_nested(std::vector<Element>& elements, const std::string& id) {
  for (Element& e : elements) {
    if (e.id == id) return &e;
    if (auto* g = std::get_if<Group>(&e.body)) {
      if (Element* found = find_nested(g->children, id)) return found;
    }
  }
  return nullptr;
}

}  // namespace

std::size_t DocumentEditor::clamp_values(const std::vector<ClampFix>& fixes) {
  Image next = image_;
  std::size_t changed = 0;
  for (const ClampFix& fix : fixes) {
    if (fix.parameter == nullptr) continue;
    double* value = nullptr;
    if (fix.element_id.empty()) {
      value = number_in(next, *fix.parameter);
    } else if (Element* e = find_nested(next.children, fix.element_id)) {
      value = number_in(*e, *fix.parameter);
    }
    if (value == nullptr) continue;
    const double clamped = clamp_to_range(*fix.parameter, *value);
    if (clamped == *value) continue;
    *value = clamped;
    ++changed;
  }
  if (changed == 0) return 0;
  before_change();
  image_ = std::move(next);
  after_change();
  return changed;
}

void DocumentEditor::replace_image_settings(const Image& settings) {
  Image next = settings;
  next.children = image_.children;
  if (next == image_) return;
  before_change();
  image_ = std::move(next);
  after_change();
}

void DocumentEditor::replace_tactile_values(const Image& image) {
  Image next = image_;
  next.children = image.children;
  if (next == image_) return;
  before_change();
  image_ = std::move(next);
  after_change();
}

void DocumentEditor::begin_gesture() {
  if (gesture_start_) return;
  gesture_start_ = current_state();
  gesture_changed_ = false;
}

void DocumentEditor::end_gesture() {
  if (!gesture_start_) return;
  if (gesture_changed_) {
    undo_.push_back(std::move(*gesture_start_));
    redo_.clear();
  }
  gesture_start_.reset();
  gesture_changed_ = false;
}

void DocumentEditor::undo() {
  end_gesture();
  if (undo_.empty()) return;
  redo_.push_back(current_state());
  State s = std::move(undo_.back());
  undo_.pop_back();
  restore(std::move(s));
}

void DocumentEditor::redo() {
  end_gesture();
  if (redo_.empty()) return;
  undo_.push_back(current_state());
  State s = std::move(redo_.back());
  redo_.pop_back();
  restore(std::move(s));
}

}  // namespace vimg::editor
