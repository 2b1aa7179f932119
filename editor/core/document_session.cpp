#include "editor/core/document_session.hpp"

#include <cstdint>

#include "editor/core/document_problems.hpp"
#include "storage/file_extension.hpp"
#include "storage/image_io.hpp"

namespace vimg::editor {

ImportQuestion import_question(const std::string& path) {
  ImportQuestion q;
  if (lower_extension(path) != ".png") return q;
  q.picture = true;
  const std::optional<PngFileKind> kind = png_file_kind(path);
  if (!kind) return q;  // the import reports it
  q.vibroimage = kind->vibroimage;
  if (kind->width_mm) q.width_mm = *kind->width_mm;
  return q;
}

Image DocumentSession::blank_image(const std::string& tool_version) {
  Image image;
  image.width_mm = 100.0;
  image.height_mm = 100.0;
  Meta meta;
  meta.tool = ToolInfo{"vimg-editor", tool_version, {}};
  image.meta = meta;
  return image;
}

DocumentSession::DocumentSession(Options options)
    : options_(std::move(options)),
      doc_(blank_image(options_.tool_version)),
      recent_(options_.recent_store),
      recovery_(options_.recovery_dir) {}

std::string DocumentSession::display_name() const {
  return path_.empty() ? "untitled" : std::filesystem::path(path_).filename().string();
}

void DocumentSession::discard_recovery_unless_pending() {
  if (!recovery_pending_) recovery_.discard();
}

void DocumentSession::new_document() {
  doc_.reset(blank_image(options_.tool_version));
  path_.clear();
  load_diagnostics_.clear();
  discard_recovery_unless_pending();
}

std::optional<std::string> DocumentSession::open(const std::string& path, const std::function<void()>& before_replace) {
  LoadResult result = load_image_file(path);
  if (!result.ok() && !result.readable) {
    recent_.remove(path);
    return result.diagnostics.empty() ? path + ": cannot open" : join_diagnostics(result.diagnostics);
  }
  // A file with problems opens with every element that could be read; its problems are listed.
  OpenedDocument opened = *open_document_with_problems(std::move(result));
  if (before_replace) before_replace();
  doc_.reset(std::move(opened.image));
  path_ = path;
  load_diagnostics_ = std::move(opened.diagnostics);
  recent_.add(path);
  discard_recovery_unless_pending();
  return std::nullopt;
}

std::optional<std::string> DocumentSession::import_into_new_document(const std::string& path,
                                                                    const ImportOptions& options,
                                                                    const std::function<void()>& before_replace) {
  ImportResult result = import_file(path, options);
  if (!result.ok()) return result.diagnostics.empty() ? path + ": cannot import" : join_diagnostics(result.diagnostics);
  if (result.opened_vibroimage) return open(path, before_replace);  // a vibroimage already: opened
  if (before_replace) before_replace();
  doc_.reset(std::move(*result.image));
  doc_.mark_unsaved();  // new and untitled: Save asks for a path, closing asks to save
  path_.clear();
  load_diagnostics_ = std::move(result.diagnostics);
  discard_recovery_unless_pending();
  return std::nullopt;
}

std::optional<std::string> DocumentSession::save_to(const std::string& path, bool becomes_document_path) {
  if (auto error = save_image_file(doc_.image(), path)) return error;
  if (becomes_document_path) {
    path_ = path;
    doc_.mark_saved();
    recovery_.discard();
  }
  recent_.add(path);
  return std::nullopt;
}

std::optional<std::string> DocumentSession::autosave_if_due(double now_s) {
  if (recovery_pending_) return std::nullopt;  // the designer decides first
  if (!doc_.dirty() || doc_.in_gesture()) return std::nullopt;
  if (doc_.change_count() == autosaved_change_ || now_s - last_autosave_s_ < options_.autosave_interval_s) {
    return std::nullopt;
  }
  std::string status = "autosaved";
  if (auto error = recovery_.save(doc_.image(), path_)) status = "autosave failed: " + *error;
  autosaved_change_ = doc_.change_count();
  last_autosave_s_ = now_s;
  return status;
}

bool DocumentSession::offer_recovery() {
  if (recovery_.adopt_orphan()) recovery_pending_ = true;
  return recovery_pending_;
}

std::optional<std::string> DocumentSession::recover() {
  recovery_pending_ = false;
  LoadResult result = load_image_file(recovery_.file());
  if (!result.ok()) return join_diagnostics(result.diagnostics);
  doc_.reset(std::move(*result.image));
  doc_.mark_unsaved();
  path_ = recovery_.recorded_origin().string();
  return std::nullopt;
}

void DocumentSession::discard_recovery() {
  recovery_pending_ = false;
  recovery_.discard();
}

}  // namespace vimg::editor
