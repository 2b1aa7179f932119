#pragma once
// A small built site in a folder of its own (build tree, web_server_tests/NAME), with a secret
// file beside it that no request may reach, and a WebServer on a free port whose log lines are kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <fstream>
#include <mutex>
#include <string>
#include <vector>

#include "web/server/web_server.hpp"

namespace vimg::test {

namespace fs = std::filesystem;
using web::kMaxRequestBodyBytes;
using web::WebServer;
using web::WebServerOptions;

inline void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

class SiteFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::path(VIMG_BINARY_DIR) / "web_server_tests" / (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(root_);
    site_ = root_ / "site";
    fs::create_directories(site_ / "images");
    fs::create_directories(site_ / "empty");
    write_text(site_ / "index.html", "<!doctype html><title>site</title>");
    write_text(site_ / "vimg.js", "export const x = 1;");
    write_text(site_ / "vimg.wasm", std::string("\0asm\1\0\0\0", 8));
    write_text(site_ / "images" / "index.json", "[\"smiley\"]");
    write_text(site_ / "images" / "smiley.vsc", "VSC1");
    write_text(root_ / "secret.txt", "the secret");
    fs::create_symlink(root_ / "secret.txt", site_ / "link_out.txt");
    fs::create_symlink(root_, site_ / "folder_out");
    fs::create_symlink("index.html", site_ / "link_in.html");
  }
  void TearDown() override { server_.reset(); }

  // Starts the server on a free port of 127.0.0.1 (its options changed by `configure` first).
  WebServer& start_server(const std::function<void(WebServerOptions&)>& configure = {}) {
    WebServerOptions options;
    options.site_dir = site_;
    options.log_line = [this](const std::string& line) {
      const std::lock_guard lock(log_mutex_);
      log_.push_back(line);
    };
    if (configure) configure(options);
    server_ = std::make_unique<WebServer>(options);
    const auto problem = server_->start();
    EXPECT_FALSE(problem) << *problem;
    return *server_;
  }
  int port() const { return server_->port(); }
  std::vector<std::string> log() {
    const std::lock_guard lock(log_mutex_);
    return log_;
  }
  bool logged(const std::string& line) {
    const std::lock_guard lock(log_mutex_);
    return std::find(log_.begin(), log_.end(), line) != log_.end();
  }

  fs::path root_, site_;
  std::unique_ptr<WebServer> server_;
  std::mutex log_mutex_;
  std::vector<std::string> log_;
};

}  // namespace vimg::test
