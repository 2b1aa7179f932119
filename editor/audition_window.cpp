#include "editor/audition_window.hpp"

#include <imgui.h>

#include <cstdio>
#include <vector>

#include "web/server/lan_address.hpp"

namespace vimg::editor {

namespace {

constexpr float kModulePx = 4.0f;
constexpr int kQuietModules = 4;

}  // namespace

AuditionWindow::~AuditionWindow() { stop(); }

void AuditionWindow::message(const std::string& line) {
  std::fprintf(stderr, "vimg-editor: audition: %s\n", line.c_str());
  const std::lock_guard lock(message_mutex_);
  last_message_ = line;
}

void AuditionWindow::start(const std::filesystem::path& image, const std::string& actuator_profile) {
  stop();
  {
    const std::lock_guard lock(message_mutex_);
    last_message_.clear();
  }
  web::WebServerOptions server_options;
  server_options.host = "0.0.0.0";
  server_options.port = 0;  // a free port: the URL says which
  std::vector<std::string> profile_errors;
  const std::optional<WebSiteOptions> site_options = web_site_options(actuator_profile, profile_errors);
  if (!site_options) {
    std::string why;
    for (const std::string& e : profile_errors) why += (why.empty() ? "" : "; ") + e;
    notices_.report_error("Audition on a device: the actuator profile cannot be used: " + why);
    return;
  }
  auto served = std::make_unique<web::ServedImages>(std::vector<std::filesystem::path>{image},
                                                    *site_options, server_options,
                                                    [this](const std::string& line) { message(line); });
  if (!served->start()) {
    const std::lock_guard lock(message_mutex_);
    notices_.report_error("Audition on a device: " + image.string() + " cannot be served: " + last_message_);
    return;
  }
  served_ = std::move(served);
  image_ = image;
  const auto lan = web::first_lan_ipv4_address();
  url_ = web::site_url(lan ? *lan : "127.0.0.1", served_->server().port());
  qr_ = web::qr_modules(url_);
  notices_.status = "Audition: " + url_;
  message("serving " + image_.filename().string() + " at " + url_);
}

void AuditionWindow::stop() {
  if (!served_) return;
  served_.reset();  // stops the watcher and the server, removes the temporary site
  notices_.status = "Audition stopped";
}

void AuditionWindow::draw(float x, float y) {
  if (!served_) return;
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Appearing);
  bool open = true;
  if (ImGui::Begin("Audition on a device", &open, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted(image_.filename().string().c_str());
    ImGui::Text("Open on a phone or tablet on this network:");
    ImGui::TextUnformatted(url_.c_str());
    if (ImGui::SmallButton("Copy URL")) ImGui::SetClipboardText(url_.c_str());
    if (qr_) {
      const float side = static_cast<float>(qr_->width + 2 * kQuietModules) * kModulePx;
      const ImVec2 origin = ImGui::GetCursorScreenPos();
      ImDrawList* draw = ImGui::GetWindowDrawList();
      draw->AddRectFilled(origin, ImVec2(origin.x + side, origin.y + side), IM_COL32(255, 255, 255, 255));
      for (int row = 0; row < qr_->width; ++row) {
        for (int column = 0; column < qr_->width; ++column) {
          if (!qr_->is_dark(row, column)) continue;
          const ImVec2 a(origin.x + static_cast<float>(column + kQuietModules) * kModulePx,
                         origin.y + static_cast<float>(row + kQuietModules) * kModulePx);
          draw->AddRectFilled(a, ImVec2(a.x + kModulePx, a.y + kModulePx), IM_COL32(0, 0, 0, 255));
        }
      }
      ImGui::Dummy(ImVec2(side, side));
    }
    ImGui::TextDisabled("Each save (Ctrl+S) reaches the open pages.");
    {
      const std::lock_guard lock(message_mutex_);
      if (!last_message_.empty()) ImGui::TextWrapped("%s", last_message_.c_str());
    }
    if (ImGui::Button("Stop")) open = false;
  }
  ImGui::End();
  if (!open) stop();
}

}  // namespace vimg::editor
