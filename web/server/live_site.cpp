#include "web/server/live_site.hpp"

namespace vimg::web {

LiveSite::LiveSite(WebServerOptions server_options, std::vector<std::filesystem::path> images, RefreshImage refresh)
    : server_(std::move(server_options)), images_(std::move(images)), refresh_(std::move(refresh)) {}

LiveSite::~LiveSite() { stop(); }

std::optional<std::string> LiveSite::start() {
  if (auto problem = server_.start()) return problem;
  if (images_.empty()) return std::nullopt;
  watcher_ = std::make_unique<ImageWatcher>(images_, [this](const std::filesystem::path& image) {
    const std::optional<std::string> name = refresh_(image);
    if (name) server_.publish_image_changed(*name);
    ++saves_seen_;
  });
  if (!watcher_->error().empty()) {
    std::string problem = watcher_->error();
    stop();
    return problem;
  }
  return std::nullopt;
}

int LiveSite::saves_seen() const { return saves_seen_; }

void LiveSite::stop() {
  watcher_.reset();
  server_.stop();
}

}  // namespace vimg::web
