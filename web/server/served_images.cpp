#include "web/server/served_images.hpp"

#include <stdlib.h>

#include <cstdio>
#include <system_error>

namespace vimg::web {

namespace fs = std::filesystem;

TemporaryFolder::TemporaryFolder(const std::string& prefix) {
  std::error_code ec;
  const fs::path base = fs::temp_directory_path(ec);
  if (ec) return;
  std::string pattern = (base / (prefix + "XXXXXX")).string();
  if (mkdtemp(pattern.data())) path_ = pattern;
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ec;
  if (!path_.empty()) fs::remove_all(path_, ec);
}

ServedImages::ServedImages(std::vector<fs::path> images, WebSiteOptions site_options, WebServerOptions server_options,
                           std::function<void(const std::string&)> report)
    : images_(std::move(images)),
      site_options_(std::move(site_options)),
      server_options_(std::move(server_options)),
      report_(std::move(report)) {}

ServedImages::~ServedImages() { stop(); }

void ServedImages::say(const std::string& line) const {
  if (report_) {
    report_(line);
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
}

bool ServedImages::start() {
  if (folder_.path().empty()) {
    say("cannot create a temporary folder for the site");
    return false;
  }
  const fs::path site = folder_.path();
  const auto reported = [this](const std::vector<Diagnostic>& diagnostics) {
    for (const Diagnostic& d : diagnostics) say(d.to_string());
    return !has_errors(diagnostics);
  };
  if (!reported(build_web_site(images_, site_options_, site))) return false;
  server_options_.site_dir = site;
  live_ = std::make_unique<LiveSite>(server_options_, images_, [this, site, reported](const fs::path& image) -> std::optional<std::string> {
    if (!reported(update_web_image(image, site_options_, site))) return std::nullopt;
    say(image.string() + " changed: pushed to the open pages");
    return web_image_name(image);
  });
  if (const auto problem = live_->start()) {
    say(*problem);
    live_.reset();
    return false;
  }
  return true;
}

void ServedImages::stop() {
  if (live_) live_->stop();
}

}  // namespace vimg::web
