#include "editor/actuator_choice.hpp"

#include <imgui.h>

#include "editor/core/layout_log.hpp"
#include "storage/shipped_data.hpp"

namespace vimg::editor {
namespace {

// Where the shipped profiles are: the working folder's assets/profiles (as a relative --actuator
// path is read), else the shipped data's (storage/shipped_data.hpp).
std::vector<std::filesystem::path> profile_folders() {
  std::vector<std::filesystem::path> folders{std::filesystem::path("assets") / "profiles"};
  if (const auto data = shipped_data_dir()) folders.push_back(*data / "profiles");
  return folders;
}

}  // namespace

ActuatorChoice::ActuatorChoice(ActuatorFeel& feel, Notices& notices, LayoutLog& layout,
                               std::filesystem::path recent_folders_store)
    : feel_(feel), notices_(notices), layout_(layout), chooser_(layout, recent_folders_store),
      remembered_(recent_folders_store.parent_path() / "actuator.txt", 1), shipped_(profile_files(profile_folders())) {}

void ActuatorChoice::restore() {
  if (!remembered_.paths().empty()) choose(remembered_.paths().front());
}

bool ActuatorChoice::choose(const std::filesystem::path& path) {
  const std::vector<std::string> errors = feel_.choose(path);
  if (errors.empty()) {
    std::error_code ec;
    // A shipped profile given by name is remembered by its file, so the next start finds it anywhere.
    const std::filesystem::path absolute = std::filesystem::absolute(resolve_profile_argument(path), ec);
    if (!ec) remembered_.add(absolute.lexically_normal().string());
    notices_.status = "designing for " + feel_.analysis().describe();
    return true;
  }
  std::string text = "cannot use the actuator profile " + path.string() + ":";
  for (const std::string& e : errors) text += "\n" + e;
  notices_.report_error(std::move(text));
  return false;
}

void ActuatorChoice::draw() {
  const std::string current = feel_.path().empty() ? "ideal (built in)" : feel_.path().filename().string();
  ImGui::TextUnformatted("Actuator");
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##actuator", current.c_str())) {
    if (ImGui::Selectable("ideal (built in)", feel_.path().empty())) {
      feel_.choose_ideal();
      if (!remembered_.paths().empty()) remembered_.remove(remembered_.paths().front());
      notices_.status = "designing for the ideal actuator";
    }
    for (const auto& p : shipped_) {
      if (ImGui::Selectable(p.filename().string().c_str(), p == feel_.path())) choose(p);
      layout_.print("actuator_item_" + p.stem().string(), ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                    ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y);
    }
    if (ImGui::Selectable("Open profile...")) {
      const std::string folder = shipped_.empty() ? std::string() : shipped_.front().parent_path().string() + "/";
      chooser_.open(FileChooser::Purpose::open, feel_.path().empty() ? folder : feel_.path().string());
    }
    layout_.print("actuator_open", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                  ImGui::GetItemRectSize().y);
    ImGui::EndCombo();
  }
  layout_.print("actuator_combo", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                ImGui::GetItemRectSize().y);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", feel_.analysis().describe().c_str());
  if (const auto result = chooser_.draw(); result && result->chosen) choose(result->path);
}

}  // namespace vimg::editor
