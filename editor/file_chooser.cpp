#include "editor/file_chooser.hpp"

#include <imgui.h>

#include <cstdio>
#include <cstdlib>

#include "editor/core/layout_log.hpp"
#include "storage/shipped_data.hpp"

namespace vimg::editor {
namespace {

namespace fs = std::filesystem;

fs::path home_folder() {
  const char* h = std::getenv("HOME");
  return h && *h ? fs::path(h) : fs::current_path();
}

bool is_folder(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

std::string size_text(std::uintmax_t bytes) {
  char s[32];
  if (bytes < 1024) {
    std::snprintf(s, sizeof s, "%ju B", bytes);
  } else if (bytes < 1024 * 1024) {
    std::snprintf(s, sizeof s, "%.1f KiB", static_cast<double>(bytes) / 1024.0);
  } else {
    std::snprintf(s, sizeof s, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  }
  return s;
}

}  // namespace

FileChooser::FileChooser(LayoutLog& layout, fs::path recent_folders_store)
    : layout_(layout), recent_folders_(std::move(recent_folders_store), 8) {}

void FileChooser::open(Purpose purpose, const std::string& initial, std::vector<std::string> recent_files) {
  purpose_ = purpose;
  filters_ = purpose == Purpose::open          ? image_filters()
             : purpose == Purpose::import_file ? import_filters()
             : purpose == Purpose::save_as     ? save_filters()
                                               : gesture_filters();
  filter_ = 0;
  recent_files_ = std::move(recent_files);
  message_.clear();
  fs::path start;
  std::string name;
  if (!initial.empty()) {
    const fs::path p(initial);
    if (p.has_parent_path() && is_folder(p.parent_path())) start = p.parent_path();
    name = p.filename().string();
  }
  if (start.empty() && !recent_folders_.paths().empty() && is_folder(recent_folders_.paths().front())) {
    start = recent_folders_.paths().front();
  }
  if (start.empty()) start = fs::current_path();
  if (purpose == Purpose::save_as && name.ends_with(".png")) filter_ = 1;
  std::snprintf(name_, sizeof name_, "%s", name.c_str());
  go_to(start);
  open_ = true;
  opening_ = true;
}

void FileChooser::go_to(const fs::path& folder) {
  folder_ = folder;
  relist();
  folder_ = listing_.folder;
}

void FileChooser::relist() { listing_ = list_folder(folder_, filters_[static_cast<std::size_t>(filter_)]); }

void FileChooser::draw_places() {
  ImGui::TextDisabled("Places");
  if (ImGui::Selectable("Home")) go_to(home_folder());
  if (const auto data = shipped_data_dir(); data && ImGui::Selectable("Examples")) go_to((*data / "examples").string());
  ImGui::Separator();
  ImGui::TextDisabled("Recent folders");
  const auto& folders = recent_folders_.paths();
  for (std::size_t i = 0; i < folders.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    const std::string label = fs::path(folders[i]).filename().string();
    if (ImGui::Selectable(label.empty() ? folders[i].c_str() : label.c_str())) go_to(folders[i]);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", folders[i].c_str());
    layout_.print("chooser_recent_" + std::to_string(i), ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                  ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y);
    ImGui::PopID();
  }
  if (!recent_files_.empty()) {
    ImGui::Separator();
    ImGui::TextDisabled("Recent files");
    for (const std::string& f : recent_files_) {
      if (ImGui::Selectable(fs::path(f).filename().c_str())) {
        go_to(fs::path(f).parent_path());
        std::snprintf(name_, sizeof name_, "%s", fs::path(f).filename().c_str());
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", f.c_str());
    }
  }
}

bool FileChooser::draw_listing() {
  bool chosen = false;
  if (listing_.error) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", listing_.error->c_str());
  std::optional<fs::path> into;
  for (const FolderEntry& e : listing_.entries) {
    const std::string label = e.folder ? e.name + "/" : e.name;
    const bool selected = !e.folder && e.name == name_;
    if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
      if (e.folder) {
        into = folder_ / e.name;
      } else {
        std::snprintf(name_, sizeof name_, "%s", e.name.c_str());
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) chosen = true;
      }
    }
    layout_.print("chooser_item_" + e.name, ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                  ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y);
    if (!e.folder) {
      ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 80);
      ImGui::TextDisabled("%s", size_text(e.size_bytes).c_str());
    }
  }
  if (listing_.truncated) ImGui::TextDisabled("(only the first %zu entries)", kMaxFolderEntries);
  if (into) go_to(*into);
  return chosen;
}

std::optional<FileChooser::Result> FileChooser::accept_name() {
  const FileFilter& filter = filters_[static_cast<std::size_t>(filter_)];
  const auto path = resolve_typed_path(name_, folder_, home_folder());
  if (!path) return std::nullopt;
  if (is_folder(*path)) {  // a typed folder is opened, not chosen
    go_to(*path);
    name_[0] = 0;
    return std::nullopt;
  }
  fs::path chosen = *path;
  const bool reading = purpose_ == Purpose::open || purpose_ == Purpose::import_file;
  if (!reading) chosen = chosen.parent_path() / with_extension(chosen.filename().string(), filter);
  if (!is_folder(chosen.parent_path())) {
    message_ = "no such folder: " + chosen.parent_path().string();
    return std::nullopt;
  }
  recent_folders_.add(chosen.parent_path().string());
  return Result{true, chosen.string()};
}

std::optional<FileChooser::Result> FileChooser::draw() {
  if (opening_) {
    ImGui::OpenPopup("File");
    opening_ = false;
    ++count_;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(760, 480), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal("File", nullptr, ImGuiWindowFlags_NoSavedSettings)) return std::nullopt;
  std::optional<Result> result;
  ImGui::TextUnformatted(purpose_ == Purpose::open      ? "Open an image (.vimg or .xml, or a .png with the XML inside):"
                         : purpose_ == Purpose::import_file
                             ? "Import a drawing (.svg) or a picture (.png) as a new document:"
                         : purpose_ == Purpose::save_as ? "Save as (.vimg or .xml for XML, .png for a picture with the XML inside):"
                                                        : "Save the recorded gesture as CSV:");
  if (ImGui::Button("Up")) go_to(parent_folder(folder_));
  layout_.print("chooser_up", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                ImGui::GetItemRectSize().y);
  ImGui::SameLine();
  ImGui::TextUnformatted(folder_.c_str());

  const float list_h = ImGui::GetContentRegionAvail().y - 3 * ImGui::GetFrameHeightWithSpacing() - 4;
  ImGui::BeginChild("##places", ImVec2(180, list_h), true);
  draw_places();
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("##listing", ImVec2(0, list_h), true);
  const bool double_clicked = draw_listing();
  ImGui::EndChild();

  ImGui::SetNextItemWidth(260);
  std::vector<const char*> labels;
  for (const FileFilter& f : filters_) labels.push_back(f.label.c_str());
  if (ImGui::Combo("##filter", &filter_, labels.data(), static_cast<int>(labels.size()))) relist();
  layout_.print("chooser_filter", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                ImGui::GetItemRectSize().y);
  if (!message_.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", message_.c_str());
  }
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  ImGui::SetNextItemWidth(-1);
  const bool entered = ImGui::InputTextWithHint("##path", "file name or path", name_, sizeof name_,
                                                ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  layout_.print("chooser_name", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                ImGui::GetItemRectSize().y);
  if (ImGui::IsItemActive()) {  // ready for typing (scripted tests wait for this)
    layout_.print("file_prompt" + std::to_string(count_), ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                  ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y);
  }
  if (entered) ImGui::SetKeyboardFocusHere(-1);  // stay in the field (e.g. after typing a folder)
  const bool ok = ImGui::Button(purpose_ == Purpose::open          ? "Open"
                                : purpose_ == Purpose::import_file ? "Import"
                                                                   : "Save", ImVec2(120, 0)) || entered || double_clicked;
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
  if (ok && name_[0] != 0) {
    result = accept_name();
  } else if (cancel) {
    result = Result{false, {}};
  }
  if (result) {
    open_ = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
  return result;
}

}  // namespace vimg::editor
