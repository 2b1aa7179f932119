#include "editor/playback.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "editor/canvas_view.hpp"
#include "editor/core/device_messages.hpp"
#include "editor/core/geometry.hpp"
#include "editor/core/layout_log.hpp"
#include "storage/palette.hpp"
#include "realtime/clock.hpp"

namespace vimg::editor {
namespace {
constexpr double kTrailS = 1.5;
constexpr std::size_t kMaxDashedMarks = 256;  // more weak primitives than this: solid outlines
ImVec2 iv(Point2Px p) { return ImVec2(p.x, p.y); }
}  // namespace

Playback::Playback(const EditorOptions& options, Notices& notices, LayoutLog& layout,
                   std::filesystem::path recent_folders_store)
    : options_(options), notices_(notices), layout_(layout),
      choice_(feel_, notices, layout, std::move(recent_folders_store)) {
  touch_ = options_.touch;
  if (!options_.actuator.empty()) {
    choice_.choose(options_.actuator);
  } else {
    choice_.restore();
  }
}

void Playback::set_on(bool on, const Image& image) {
  if (on == on_) return;
  if (on) {
    if (!play_) {
      const OutputChoice choice = options_.output;
      play_ = std::make_unique<PlaySession>([choice](std::string& error) { return make_output(choice, error); },
                                            options_.sample_rate_hz);
    }
    play_->set_touch_compensation(touch_);
    if (auto error = play_->start(image)) {
      notices_.report_error("cannot play to " + options_.output.text + ": " + *error);
      return;
    }
    if (!options_.record_gesture.empty()) play_->set_recording(true);
    pointer_time_.set_enabled(true);
    on_ = true;
    notices_.status = "playing to " + options_.output.text;
    return;
  }
  on_ = false;
  mouse_finger_down_ = false;
  pointer_time_.set_enabled(false);
  if (!play_) return;
  play_->stop();
  notices_.status = "drawing";
  show_device_messages();  // the last faults of the session, drained by the stop
  if (const DriveTap* tap = play_->tap()) {
    std::vector<double> lat = tap->latencies_s();
    if (!lat.empty()) {
      std::sort(lat.begin(), lat.end());
      std::fprintf(stderr, "vimg-editor: %zu drive onsets, event-to-drive latency ms: median %.2f max %.2f\n",
                   lat.size(), lat[lat.size() / 2] * 1e3, lat.back() * 1e3);
    }
  }
  if (!options_.record_gesture.empty() && play_->recording()) {
    if (auto error = play_->recorded_gesture().save(options_.record_gesture)) notices_.report_error(*error);
  }
}

void Playback::show_device_messages() {
  if (!play_) return;
  editor::show_device_messages(play_->take_device_messages(), on_ ? "playing to " + options_.output.text : "drawing",
                               notices_);
}

void Playback::follow(const Image& image, std::uint64_t change_count) {
  if (!on_ || !play_ || !play_->playing() || played_change_ == change_count) return;
  play_->update(image);
  played_change_ = change_count;
}

std::optional<std::string> Playback::save_gesture(const std::string& path) const {
  if (!play_) return std::string("no gesture recorded");
  return play_->recorded_gesture().save(path);
}

void Playback::handle_input(const SDL_Event& event, const CanvasView& canvas, SDL_Window* window, bool popup_open) {
  if (!on_ || !play_ || !play_->playing()) return;
  const double now = pointer_time_.time_of(event, monotonic_s());
  auto mm = [&](float x, float y) { return canvas.view().to_mm(Point2Px{x, y}); };
  switch (event.type) {
    case SDL_MOUSEBUTTONDOWN:
      if (event.button.which == SDL_TOUCH_MOUSEID || event.button.button != SDL_BUTTON_LEFT || popup_open) break;
      if (canvas.inside_px(static_cast<float>(event.button.x), static_cast<float>(event.button.y))) {
        const Point2Mm p = mm(static_cast<float>(event.button.x), static_cast<float>(event.button.y));
        play_->touch(0, TouchPhase::down, p.x_mm, p.y_mm, now);
        mouse_finger_down_ = true;
      }
      break;
    case SDL_MOUSEMOTION:
      if (event.motion.which == SDL_TOUCH_MOUSEID || !mouse_finger_down_) break;
      {
        const Point2Mm p = mm(static_cast<float>(event.motion.x), static_cast<float>(event.motion.y));
        play_->touch(0, TouchPhase::move, p.x_mm, p.y_mm, now);
      }
      break;
    case SDL_MOUSEBUTTONUP:
      if (event.button.which == SDL_TOUCH_MOUSEID || event.button.button != SDL_BUTTON_LEFT || !mouse_finger_down_) break;
      {
        const Point2Mm p = mm(static_cast<float>(event.button.x), static_cast<float>(event.button.y));
        play_->touch(0, TouchPhase::up, p.x_mm, p.y_mm, now);
        mouse_finger_down_ = false;
      }
      break;
    case SDL_FINGERDOWN:
    case SDL_FINGERMOTION:
    case SDL_FINGERUP: {
      int w = 0, h = 0;
      SDL_GetWindowSize(window, &w, &h);
      const float x = event.tfinger.x * static_cast<float>(w);
      const float y = event.tfinger.y * static_cast<float>(h);
      // Finger 0 is the mouse; touches take 1..9 by their order of arrival.
      const int finger = 1 + static_cast<int>(event.tfinger.fingerId % 9);
      const Point2Mm p = mm(x, y);
      const bool down = play_->fingers()[static_cast<std::size_t>(finger)].has_value();
      if (event.type == SDL_FINGERDOWN) {
        if (canvas.inside_px(x, y) && !popup_open) play_->touch(finger, TouchPhase::down, p.x_mm, p.y_mm, now);
      } else if (event.type == SDL_FINGERMOTION) {
        if (down) play_->touch(finger, TouchPhase::move, p.x_mm, p.y_mm, now);
      } else if (down) {
        play_->touch(finger, TouchPhase::up, p.x_mm, p.y_mm, now);
      }
      break;
    }
    default: break;
  }
}

bool Playback::contacted(const Element& element) const {
  if (!on_ || !play_) return false;
  for (const auto& f : play_->fingers()) {
    if (f && element_contains(element, Point2Mm{f->x_mm, f->y_mm}, 0.0)) return true;
  }
  return false;
}

void Playback::draw_overlay(ImDrawList* dl, const Viewport& view) const {
  if (!on_ || !play_) return;
  const double now = monotonic_s();
  const auto& trail = play_->trail();
  for (std::size_t i = 1; i < trail.size(); ++i) {
    const double age = now - trail[i].time_s;
    if (age > kTrailS) continue;
    const int alpha = static_cast<int>(std::clamp(1.0 - age / kTrailS, 0.0, 1.0) * 220);
    if (trail[i].time_s - trail[i - 1].time_s > 0.2) continue;  // a new stroke
    dl->AddLine(iv(view.to_px({trail[i - 1].x_mm, trail[i - 1].y_mm})), iv(view.to_px({trail[i].x_mm, trail[i].y_mm})),
                IM_COL32(200, 40, 200, alpha), 3.0f);
  }
  for (const auto& f : play_->fingers()) {
    if (f) dl->AddCircle(iv(view.to_px({f->x_mm, f->y_mm})), 9.0f, IM_COL32(200, 40, 200, 255), 0, 2.0f);
  }
}

bool Playback::draw_controls() {
  choice_.draw();
  const bool pressed = ImGui::Button(on_ ? "Stop playing (F5)" : "Play (F5)", ImVec2(-1, 30));
  layout_.print("play_button", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                ImGui::GetItemRectSize().y);
  if (on_ && play_) {
    bool rec = play_->recording();
    if (ImGui::Checkbox("Record gesture", &rec)) play_->set_recording(rec);
    ImGui::TextDisabled("%zu samples recorded", play_->recorder().samples().size());
    ImGui::TextWrapped("Rub the canvas with the mouse or your fingers.");
  }
  return pressed;
}

void Playback::draw_scope(float x, float y, float w, float h) {
  if (play_) play_->forget_trail_older_than(monotonic_s() - kTrailS);
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Drive (oscilloscope)", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const DriveTap* tap = play_ ? play_->tap() : nullptr;
  const double rate = tap ? tap->sample_rate_hz() : 0.0;
  const std::size_t count = rate > 0 ? static_cast<std::size_t>(rate * 0.1) : 800;  // the last 100 ms
  if (tap) tap->copy_recent(scope_samples_, count);
  const LoopStats stats = play_ ? play_->stats() : LoopStats{};
  if (tap) {
    predicted_.set_response(feel_.profile().response, feel_.generation());
    predicted_.update(*tap);
    predicted_.recent(count, scope_samples_, scope_acceleration_);
  } else {
    scope_samples_.assign(count, 0.0f);
    scope_acceleration_.assign(count, 0.0f);
  }
  ImGui::Text("last 100 ms at %.0f Hz | loop %.0f Hz, jitter p99 %.2f ms | overruns %llu | contacts %llu", rate,
              stats.measured_rate_hz, stats.jitter_p99_s * 1e3, static_cast<unsigned long long>(stats.overruns),
              static_cast<unsigned long long>(stats.active_contacts));
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float half = std::max(40.0f, (avail.x - ImGui::GetStyle().ItemSpacing.x) * 0.5f);
  const ImVec2 plot(half, std::max(20.0f, avail.y - ImGui::GetTextLineHeightWithSpacing() - ImGui::GetStyle().ItemSpacing.y));
  ImGui::BeginGroup();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "drive");
  ImGui::PushStyleColor(ImGuiCol_PlotLines, ImVec4(0.55f, 0.75f, 1.0f, 1.0f));
  ImGui::PlotLines("##drive", scope_samples_.data(), static_cast<int>(scope_samples_.size()), 0, nullptr, -1.0f, 1.0f,
                   plot);
  ImGui::PopStyleColor();
  layout_.print("scope_drive", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                ImGui::GetItemRectSize().y);
  ImGui::EndGroup();
  ImGui::SameLine();
  ImGui::BeginGroup();
  const std::string label = "predicted acceleration on " + feel_.profile().name;
  ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.25f, 1.0f), "%s", label.c_str());
  ImGui::PushStyleColor(ImGuiCol_PlotLines, ImVec4(1.0f, 0.6f, 0.25f, 1.0f));
  ImGui::PlotLines("##acceleration", scope_acceleration_.data(), static_cast<int>(scope_acceleration_.size()), 0,
                   nullptr, -1.0f, 1.0f, plot);
  ImGui::PopStyleColor();
  layout_.print("scope_acceleration", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y);
  ImGui::EndGroup();
  ImGui::End();
}

void Playback::draw_feel_marks(ImDrawList* dl, const Viewport& view) const {
  constexpr float kGapPx = 4.0f, kDashPx = 7.0f;
  const palette::Rgb8 c = palette::kWeakOnActuator;
  const ImU32 colour = IM_COL32(c.r, c.g, c.b, 255);
  const auto dashed = [&](ImVec2 a, ImVec2 b) {
    const float dx = b.x - a.x, dy = b.y - a.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    for (float t = 0.0f; t < length; t += kDashPx + kGapPx) {
      const float u0 = t / length, u1 = std::min(t + kDashPx, length) / length;
      dl->AddLine(ImVec2(a.x + dx * u0, a.y + dy * u0), ImVec2(a.x + dx * u1, a.y + dy * u1), colour, 2.0f);
    }
  };
  int n = 0;
  const bool many = feel_.last_marks().size() > kMaxDashedMarks;
  for (const FeltMark& m : feel_.last_marks()) {
    const Point2Px p0 = view.to_px({m.bounds.x0_mm, m.bounds.y0_mm});
    const Point2Px p1 = view.to_px({m.bounds.x1_mm, m.bounds.y1_mm});
    const ImVec2 a(std::min(p0.x, p1.x) - 3.0f, std::min(p0.y, p1.y) - 3.0f);
    const ImVec2 b(std::max(p0.x, p1.x) + 3.0f, std::max(p0.y, p1.y) + 3.0f);
    if (layout_.enabled()) layout_.print("weak_mark" + std::to_string(n++) + "_" + m.id, a.x, a.y, b.x - a.x, b.y - a.y);
    const ImVec2 clip_min = dl->GetClipRectMin(), clip_max = dl->GetClipRectMax();
    if (b.x < clip_min.x || b.y < clip_min.y || a.x > clip_max.x || a.y > clip_max.y) continue;
    // Small marks (too few dashes to read) and many marks (dashes would cost more than the frame)
    // are drawn solid.
    if (many || (b.x - a.x < 4.0f * kDashPx && b.y - a.y < 4.0f * kDashPx)) {
      dl->AddRect(a, b, colour, 0.0f, 0, 2.0f);
      continue;
    }
    dashed(a, ImVec2(b.x, a.y));
    dashed(ImVec2(b.x, a.y), b);
    dashed(b, ImVec2(a.x, b.y));
    dashed(ImVec2(a.x, b.y), a);
  }
}

}  // namespace vimg::editor
