#pragma once
// A built web site served while its images are edited: the server (web/server/web_server.hpp)
// and a watcher of the image files (web/server/image_watcher.hpp). On each save of an image, the
// site's copy is rewritten (the `refresh` callback: update_web_image of web/site_builder) and,
// once it is, every open page is told (an "image" event with the name the callback returns). An
// image that no longer compiles is logged by the callback and leaves the pages as they are. Used
// by `vimg serve` and by the editor's "Audition on a device".
#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "web/server/image_watcher.hpp"
#include "web/server/web_server.hpp"

namespace vimg::web {

// Rewrites the site's copy of one saved image; returns the name the page knows it by
// (images/NAME.vsc), or nothing when it could not (the callback has said why).
using RefreshImage = std::function<std::optional<std::string>(const std::filesystem::path& image)>;

class LiveSite {
 public:
  LiveSite(WebServerOptions server_options, std::vector<std::filesystem::path> images, RefreshImage refresh);
  ~LiveSite();  // the watcher stops first, then the server
  LiveSite(const LiveSite&) = delete;
  LiveSite& operator=(const LiveSite&) = delete;

  // Starts the server, then the watcher. Returns the problem, or nothing.
  std::optional<std::string> start();
  WebServer& server() { return server_; }
  // Saves handled so far (refreshed or not): for tests and the editor's status line.
  int saves_seen() const;
  void stop();

 private:
  WebServer server_;
  std::vector<std::filesystem::path> images_;
  RefreshImage refresh_;
  std::unique_ptr<ImageWatcher> watcher_;
  std::atomic<int> saves_seen_{0};
};

}  // namespace vimg::web
