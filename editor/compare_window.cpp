#include "editor/compare_window.hpp"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "editor/core/layout_log.hpp"
#include "editor/worker_window.hpp"

namespace vimg::editor {

namespace {

// One comparison runs at a time: the stop request of the one under way (run_compare asks a plain
// function).
std::atomic<bool> g_stop_requested{false};
bool stop_requested() { return g_stop_requested.load(std::memory_order_relaxed); }

const ImVec4 kWarningColour(1.0f, 0.85f, 0.4f, 1.0f);
const ImVec4 kErrorColour(1.0f, 0.45f, 0.4f, 1.0f);

}  // namespace

CompareWindow::~CompareWindow() { stop(); }

bool CompareWindow::running() const {
  const std::lock_guard lock(mutex_);
  return running_;
}

void CompareWindow::stop() {
  if (!worker_.joinable()) return;
  g_stop_requested.store(true);
  worker_.join();
  g_stop_requested.store(false);
}

void CompareWindow::start(std::vector<std::filesystem::path> images, study::CompareActuator actuator) {
  stop();
  image_count_ = images.size();
  actuator_name_ = actuator.name;
  images_ = images;
  actuator_ = actuator;
  propose_requested_ = false;
  {
    const std::lock_guard lock(mutex_);
    result_.reset();
    running_ = true;
  }
  open_ = true;
  place_ = true;
  study::CompareRequest request;
  request.inputs = std::move(images);
  request.actuator = std::move(actuator);
  request.should_stop = stop_requested;
  worker_ = std::thread([this, request = std::move(request)] {
    study::CompareResult result = study::run_compare(request);
    {
      const std::lock_guard lock(mutex_);
      result_ = std::move(result);
      running_ = false;
    }
    wake_gui();
  });
}

std::optional<std::pair<std::vector<std::filesystem::path>, study::CompareActuator>> CompareWindow::take_proposal_request() {
  if (!propose_requested_) return std::nullopt;
  propose_requested_ = false;
  return std::pair{images_, actuator_};
}

void CompareWindow::draw(float x, float y, float w, float h) {
  if (!open_) return;
  if (place_) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::SetNextWindowFocus();
    place_ = false;
  }
  if (!ImGui::Begin("Predicted confusion", &open_, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  layout_.print("compare_window", ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowSize().x,
                ImGui::GetWindowSize().y);
  const std::lock_guard lock(mutex_);
  if (running_) {
    ImGui::Text("Rendering and comparing %zu images on %s...", image_count_, actuator_name_.c_str());
    ImGui::TextDisabled("each under the standard exploration, as vimg compare does");
  } else if (result_) {
    draw_result(*result_);
  }
  ImGui::End();
}

void CompareWindow::draw_result(const study::CompareResult& r) {
  for (const Diagnostic& d : r.diagnostics) {
    ImGui::PushStyleColor(ImGuiCol_Text, d.severity == Diagnostic::Severity::error ? kErrorColour : kWarningColour);
    ImGui::TextWrapped("%s", d.to_string().c_str());
    ImGui::PopStyleColor();
  }
  if (!r.ok()) {
    if (r.interrupted) ImGui::TextUnformatted("Stopped.");
    print_last_item(layout_, "compare_failed");
    return;
  }
  ImGui::TextWrapped("On %s, explored by %s.", r.actuator.name.c_str(),
                     r.exploration ? study::describe(*r.exploration).c_str() : "the given gestures");
  if (r.warnings.empty()) {
    ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "No pair is likely to be confused (p below %.2f).",
                       r.choice.likely_confused_p);
    print_last_item(layout_, "compare_no_warning");
  }
  for (std::size_t k = 0; k < r.warnings.size(); ++k) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWarningColour);
    ImGui::TextWrapped("%s", r.warnings[k].c_str());
    ImGui::PopStyleColor();
    print_last_item(layout_, "compare_warning" + std::to_string(k));
  }
  const bool images_only = std::all_of(r.inputs.begin(), r.inputs.end(), [](const study::CompareInput& in) {
    return in.kind == study::CompareInputKind::image;
  });
  if (images_only) {
    if (ImGui::Button("Propose changes")) propose_requested_ = true;
    print_last_item(layout_, "propose_button");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Which tactile parameters to change, and how far, so that people tell these images apart (as "
                        "vimg separate proposes it)");
  }
  ImGui::Spacing();
  ImGui::TextDisabled("rows: presented; columns: chosen; each row sums to 1");
  draw_matrix(r);
}

void CompareWindow::draw_matrix(const study::CompareResult& r) {
  const int n = static_cast<int>(r.inputs.size());
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX |
                                ImGuiTableFlags_ScrollY;
  const float height = std::min(ImGui::GetContentRegionAvail().y, ImGui::GetTextLineHeightWithSpacing() * static_cast<float>(n + 1) +
                                                                      ImGui::GetStyle().CellPadding.y * 2.0f * static_cast<float>(n + 1) + 4.0f);
  if (!ImGui::BeginTable("##confusion", n + 1, flags, ImVec2(0.0f, std::max(height, 40.0f)))) return;
  ImGui::TableSetupScrollFreeze(1, 1);
  ImGui::TableSetupColumn("presented \\ chosen");
  for (const study::CompareInput& in : r.inputs) ImGui::TableSetupColumn(in.label.c_str());
  ImGui::TableHeadersRow();
  for (std::size_t i = 0; i < r.inputs.size(); ++i) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(r.inputs[i].label.c_str());
    for (std::size_t j = 0; j < r.inputs.size(); ++j) {
      ImGui::TableSetColumnIndex(static_cast<int>(j) + 1);
      const double p = r.predicted_confusion[i][j];
      ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, confusion_shade(p));
      ImGui::Text("%.2f", p);
      if (ImGui::IsItemHovered()) {
        const CueDistances& d = r.cues[i][j];
        static_assert(kCueCount == 3, "the tooltip names every cue");
        ImGui::SetTooltip("%s presented, %s chosen: p = %.3f\n%.1f JNDs apart (%s %.1f, %s %.1f, %s %.1f), ST-SIM %.3f",
                          r.inputs[i].label.c_str(), r.inputs[j].label.c_str(), p, r.distance_jnd[i][j],
                          cue_name(0).data(), d[0], cue_name(1).data(), d[1], cue_name(2).data(), d[2], r.stsim[i][j]);
      }
    }
  }
  ImGui::EndTable();
  print_last_item(layout_, "compare_matrix");
}

}  // namespace vimg::editor
