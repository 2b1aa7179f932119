// The "Proposed changes" window's actions (editor_app.hpp, proposal_window.hpp): open the image a
// change is for, make a change (or every change of an image) as one undoable edit, and audition a
// change: playing mode plays the document with the change made, without touching the document,
// until playing stops or the document changes.
#include <filesystem>

#include "editor/editor_app.hpp"

namespace vimg::editor {

namespace {

bool same_file(const std::string& a, const std::filesystem::path& b) {
  if (a.empty()) return false;
  std::error_code ec;
  return a == b.string() || std::filesystem::equivalent(a, b, ec);
}

// The document with the changes made, in order.
Image with_changes(const Image& document, const std::vector<study::ParameterChange>& changes) {
  Image image = document;
  for (const study::ParameterChange& c : changes) image = study::apply_change(image, c);
  return image;
}

}  // namespace

void EditorApp::handle_proposal_action(const ProposalAction& a) {
  if (a.kind == ProposalAction::Kind::open) {
    request(PendingAction::open_file, a.image.string());
    return;
  }
  if (a.kind == ProposalAction::Kind::stop_audition) {
    set_play_mode(false);
    return;
  }
  if (!same_file(session_.path(), a.image)) {
    notices_.report_error("open " + a.image.filename().string() + " first: its changes apply to the open document");
    return;
  }
  DocumentEditor& doc = session_.editor();
  const Image changed = with_changes(doc.image(), a.changes);
  if (a.kind == ProposalAction::Kind::audition) {
    auditioned_ = changed;
    audition_label_ = a.label;
    audition_of_change_ = doc.change_count();
    ++audition_generation_;
    set_play_mode(true);
    notices_.status = "auditioning " + a.label + ": rub the canvas; stop playing to end it";
    return;
  }
  // apply and apply_all: one undoable edit each.
  doc.replace_tactile_values(changed);
  notices_.status = "applied " + a.label + " (Ctrl+Z undoes it)";
}

void EditorApp::follow_document_or_audition() {
  const DocumentEditor& doc = session_.editor();
  if (auditioned_ && (!playback_.on() || doc.change_count() != audition_of_change_)) auditioned_.reset();
  proposal_.set_auditioning(auditioned_ ? audition_label_ : std::string());
  if (auditioned_) {
    // A change count of its own, never one of the document's, so the player takes it up once.
    playback_.follow(*auditioned_, (std::uint64_t{1} << 63) + audition_generation_);
    layout_.print("audition_on", 0.0f, 0.0f, 0.0f, 0.0f);
    return;
  }
  playback_.follow(doc.image(), doc.change_count());
}

}  // namespace vimg::editor
