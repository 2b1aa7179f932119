#pragma once
// Images served to browsers while they are edited (vimg serve IMAGE..., the editor's "Audition on a
// device"): their site is built (build_web_site) into a private temporary folder, served by a
// LiveSite, and each save is compiled again (update_web_image) and pushed to the open pages. The
// folder is removed when this ends.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "web/server/live_site.hpp"
#include "web/site_builder/web_site.hpp"

namespace vimg::web {

// A folder only this user can read (mkdtemp: 0700, in TMPDIR or /tmp), removed with what it holds.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(const std::string& prefix);
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }  // empty if it could not be made

 private:
  std::filesystem::path path_;
};

class ServedImages {
 public:
  // `report` receives the diagnostics (FILE:LINE: error: ...) and a line per pushed save; by
  // default they go to stderr. server_options.site_dir is ignored (the temporary folder is served).
  ServedImages(std::vector<std::filesystem::path> images, WebSiteOptions site_options, WebServerOptions server_options,
               std::function<void(const std::string&)> report = {});
  ~ServedImages();
  ServedImages(const ServedImages&) = delete;
  ServedImages& operator=(const ServedImages&) = delete;

  // Builds the site and starts serving. False when the site has errors (reported) or the server
  // could not start (reported).
  bool start();
  WebServer& server() { return live_->server(); }
  bool running() const { return live_ && live_->server().running(); }
  void stop();

 private:
  void say(const std::string& line) const;

  std::vector<std::filesystem::path> images_;
  WebSiteOptions site_options_;
  WebServerOptions server_options_;
  std::function<void(const std::string&)> report_;
  TemporaryFolder folder_{"vimg-serve-"};
  std::unique_ptr<LiveSite> live_;
};

}  // namespace vimg::web
