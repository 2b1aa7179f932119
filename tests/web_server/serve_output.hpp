#pragma once
// `vimg serve` as a child process whose stdout and stderr both go to files of the test's own folder,
// so that a test can wait for any line it prints (the URL on stdout, a save's errors on stderr) and
// read the LAN URL and the QR code as a person sees them. The page's files are stand-ins
// (serve_process.hpp). Every wait is for a state, bounded by kHangBound only to end a hang.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "tests/net/raw_http.hpp"
#include "tests/web_server/serve_process.hpp"

namespace vimg::test {

inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

class ServeOutput {
 public:
  // `vimg serve ARGS... --port 0` in `dir` (VIMG_WEB_ASSETS=dir/assets, TMPDIR=dir/tmp).
  ServeOutput(const std::vector<std::string>& args, const std::filesystem::path& dir)
      : out_(dir / "serve.stdout"), err_(dir / "serve.stderr"), child_(start(args, dir, out_, err_)) {}

  std::string out() const { return file_text(out_); }
  std::string err() const { return file_text(err_); }

  // Waits until stdout (or stderr) holds `text`: true, or false when the program ended first or
  // the bound passed.
  bool wait_for_out(const std::string& text) { return wait_for(out_, text); }
  bool wait_for_err(const std::string& text) { return wait_for(err_, text); }

  // The port of the printed URL "http://HOST:PORT/", once the line that says it is complete; 0 if the
  // program ended first.
  int wait_for_port() {
    if (!wait_for_out(" (Ctrl-C stops)\n")) return 0;
    const std::string text = out();
    const std::size_t scheme = text.find("http://");
    const std::size_t slash = text.find('/', scheme + 7);
    const std::size_t colon = text.rfind(':', slash);
    if (scheme == std::string::npos || slash == std::string::npos || colon == std::string::npos || colon < scheme + 7) return 0;
    return std::stoi(text.substr(colon + 1, slash - colon - 1));
  }

  int stop_with(int signal_number) { return child_->stop_with(signal_number); }

 private:
  static std::unique_ptr<ServeChild> start(const std::vector<std::string>& args, const std::filesystem::path& dir,
                                           const std::filesystem::path& out, const std::filesystem::path& err) {
    std::filesystem::create_directories(dir / "tmp");
    const int out_fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const int err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    auto child = std::make_unique<ServeChild>(args, dir / "assets", dir / "tmp", out_fd, err_fd);
    close(out_fd);
    close(err_fd);
    return child;
  }

  bool wait_for(const std::filesystem::path& file, const std::string& text) {
    const auto give_up = std::chrono::steady_clock::now() + kHangBound;
    while (std::chrono::steady_clock::now() < give_up) {
      if (file_text(file).find(text) != std::string::npos) return true;
      if (child_->ended()) return file_text(file).find(text) != std::string::npos;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }

  std::filesystem::path out_, err_;
  std::unique_ptr<ServeChild> child_;
};

}  // namespace vimg::test
