#include "editor/proposal_window.hpp"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <atomic>
#include <memory>

#include "editor/core/layout_log.hpp"
#include "editor/worker_window.hpp"
#include "hal/felt_analysis.hpp"

namespace vimg::editor {

namespace {

// One search runs at a time: the stop request of the one under way (run_separate asks a plain
// function).
std::atomic<bool> g_stop_requested{false};
bool stop_requested() { return g_stop_requested.load(std::memory_order_relaxed); }

const ImVec4 kGood(0.5f, 0.9f, 0.5f, 1.0f);
const ImVec4 kWarning(1.0f, 0.85f, 0.4f, 1.0f);
const ImVec4 kError(1.0f, 0.45f, 0.4f, 1.0f);

// The editor's font has no arrow: "period 2.2 -> 3.1 mm".
std::string plain(std::string text) {
  const std::string arrow = "\u2192";
  for (std::size_t at = text.find(arrow); at != std::string::npos; at = text.find(arrow, at)) text.replace(at, arrow.size(), "->");
  return text;
}

bool same_file(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code ec;
  return a == b || std::filesystem::equivalent(a, b, ec);
}

}  // namespace

ProposalWindow::~ProposalWindow() { stop(); }

bool ProposalWindow::running() const {
  const std::lock_guard lock(mutex_);
  return running_;
}

void ProposalWindow::stop() {
  if (!worker_.joinable()) return;
  g_stop_requested.store(true);
  worker_.join();
  g_stop_requested.store(false);
}

void ProposalWindow::start(std::vector<std::filesystem::path> images, study::CompareActuator actuator) {
  stop();
  image_count_ = images.size();
  {
    const std::lock_guard lock(mutex_);
    result_.reset();
    progress_.clear();
    running_ = true;
  }
  open_ = true;
  place_ = true;
  action_.reset();
  worker_ = std::thread([this, images = std::move(images), actuator = std::move(actuator)] {
    study::SeparateRequest q;
    q.inputs = images;
    q.actuator = actuator;
    // The worker's own felt analysis: the GUI may choose another profile meanwhile.
    std::shared_ptr<FeltAnalysis> felt;
    if (!actuator.file.empty()) {
      FeltAnalysisLoad loaded = load_felt_analysis_file(actuator.file);
      felt = std::move(loaded.analysis);
    }
    if (felt) {
      q.weak_primitives = [felt](const Image& image) { return weak_primitive_indices(image, *felt); };
      q.felt_band = felt->describe();
    }
    q.should_stop = stop_requested;
    q.progress = [this](const std::string& line) {
      const std::lock_guard lock(mutex_);
      progress_ = line;
    };
    study::SeparateResult result = study::run_separate(q);
    {
      const std::lock_guard lock(mutex_);
      result_ = std::move(result);
      running_ = false;
    }
    wake_gui();
  });
}

std::optional<ProposalAction> ProposalWindow::take_action() {
  std::optional<ProposalAction> a = std::move(action_);
  action_.reset();
  return a;
}

void ProposalWindow::draw(float x, float y, float w, float h, const std::string& open_document) {
  if (!open_) return;
  if (!auditioning_.empty()) {
    // Out of the canvas's way while the designer rubs it: one line and a way back.
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(w, 0.0f), ImGuiCond_Always);
    (void)h;
    ImGui::Begin("Auditioning", nullptr, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize);
    ImGui::TextWrapped("Auditioning %s: rub the canvas.", auditioning_.c_str());
    if (ImGui::Button("Stop audition")) action_ = ProposalAction{ProposalAction::Kind::stop_audition, {}, {}, auditioning_};
    print_last_item(layout_, "proposal_stop_audition");
    ImGui::End();
    return;
  }
  if (place_) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::SetNextWindowFocus();
    place_ = false;
  }
  if (!ImGui::Begin("Proposed changes", &open_, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  layout_.print("proposal_window", ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowSize().x,
                ImGui::GetWindowSize().y);
  const std::lock_guard lock(mutex_);
  if (running_) {
    ImGui::Text("Searching the tactile parameters of %zu images...", image_count_);
    ImGui::TextDisabled("%s", progress_.c_str());
  } else if (result_) {
    draw_result(*result_, open_document);
  }
  ImGui::End();
}

void ProposalWindow::draw_result(const study::SeparateResult& r, const std::string& open_document) {
  for (const Diagnostic& d : r.diagnostics) {
    ImGui::PushStyleColor(ImGuiCol_Text, d.severity == Diagnostic::Severity::error ? kError : kWarning);
    ImGui::TextWrapped("%s", d.to_string().c_str());
    ImGui::PopStyleColor();
  }
  if (!r.ok()) {
    if (r.interrupted) ImGui::TextUnformatted("Stopped.");
    print_last_item(layout_, "proposal_failed");
    return;
  }
  if (r.already_distinct) {
    ImGui::TextColored(kGood, "Every image is already identified at least %.0f %% of the time: nothing to change.",
                       100.0 * r.target);
    print_last_item(layout_, "proposal_none");
    return;
  }
  if (r.reached) {
    ImGui::TextColored(kGood, "Every image identified at least %.0f %% of the time for %.1f JNDs of change:",
                       100.0 * r.target, r.total_change_jnd());
  } else {
    ImGui::TextColored(kWarning, "The target of %.0f %% is out of reach; the best set found:", 100.0 * r.target);
    for (const std::string& l : r.limits) ImGui::BulletText("%s", l.c_str());
  }
  print_last_item(layout_, "proposal_ready");
  for (std::size_t i = 0; i < r.images.size(); ++i) draw_image(r.images[i], i, same_file(r.images[i].path, open_document));
  ImGui::Spacing();
  ImGui::TextDisabled("predicted confusion before | after (rows: presented; columns: chosen)");
  draw_matrix("##before", r, r.before.predicted_confusion);
  ImGui::SameLine();
  draw_matrix("##after", r, r.confusion_after);
  print_last_item(layout_, "proposal_matrices");
}

void ProposalWindow::draw_image(const study::SeparateImage& im, std::size_t index, bool is_open) {
  ImGui::PushID(static_cast<int>(index));
  ImGui::Separator();
  ImGui::Text("%s: %.0f %% -> %.0f %% identified, %.1f JNDs of change", im.label.c_str(), 100.0 * im.identified_before,
              100.0 * im.identified_after, im.change_jnd);
  if (im.changes.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled(im.kept ? "(kept)" : "(unchanged)");
    ImGui::PopID();
    return;
  }
  const std::string prefix = "proposal_image" + std::to_string(index);
  layout_.print(prefix + "_is_" + std::filesystem::path(im.path).filename().string(), 0.0f, 0.0f, 0.0f, 0.0f);
  if (!is_open) {
    ImGui::SameLine();
    if (ImGui::SmallButton("Open")) action_ = ProposalAction{ProposalAction::Kind::open, im.path, {}, im.label};
    print_last_item(layout_, prefix + "_open");
  } else {
    ImGui::SameLine();
    if (ImGui::SmallButton("Apply all"))
      action_ = ProposalAction{ProposalAction::Kind::apply_all, im.path, im.changes, im.label + ": every change"};
    print_last_item(layout_, prefix + "_apply_all");
    ImGui::SameLine();
    if (ImGui::SmallButton("Audition all"))
      action_ = ProposalAction{ProposalAction::Kind::audition, im.path, im.changes, im.label + ": every change"};
    print_last_item(layout_, prefix + "_audition_all");
  }
  for (std::size_t k = 0; k < im.changes.size(); ++k) {
    const study::ParameterChange& c = im.changes[k];
    ImGui::PushID(static_cast<int>(k));
    ImGui::BulletText("%s", plain(c.text).c_str());
    if (is_open) {
      const std::string name = prefix + "_change" + std::to_string(k);
      ImGui::SameLine();
      if (ImGui::SmallButton("Audition"))
        action_ = ProposalAction{ProposalAction::Kind::audition, im.path, {c}, im.label + ": " + plain(c.text)};
      print_last_item(layout_, name + "_audition");
      ImGui::SameLine();
      if (ImGui::SmallButton("Apply"))
        action_ = ProposalAction{ProposalAction::Kind::apply, im.path, {c}, im.label + ": " + plain(c.text)};
      print_last_item(layout_, name + "_apply");
    }
    ImGui::PopID();
  }
  ImGui::PopID();
}

void ProposalWindow::draw_matrix(const char* id, const study::SeparateResult& r, const PerceptionMatrix& m) {
  const int n = static_cast<int>(m.size());
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit;
  const float width = std::max(120.0f, (ImGui::GetContentRegionAvail().x - 10.0f) / 2.0f);
  if (!ImGui::BeginTable(id, n, flags, ImVec2(width, 0.0f))) return;
  const float cell = ImGui::CalcTextSize("0.00").x;
  for (int j = 0; j < n; ++j) ImGui::TableSetupColumn(nullptr, ImGuiTableColumnFlags_WidthFixed, cell);
  for (int i = 0; i < n; ++i) {
    ImGui::TableNextRow();
    for (int j = 0; j < n; ++j) {
      ImGui::TableSetColumnIndex(j);
      const double p = m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, confusion_shade(p));
      ImGui::Text("%.2f", p);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s presented, %s chosen: p = %.3f", r.images[static_cast<std::size_t>(i)].label.c_str(),
                          r.images[static_cast<std::size_t>(j)].label.c_str(), p);
    }
  }
  ImGui::EndTable();
}

}  // namespace vimg::editor
