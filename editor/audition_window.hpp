#pragma once
// "Audition on a device" (Mode menu): the open document's saved file served to phones and tablets
// on the LAN as `vimg serve IMAGE --lan` serves it (web/server/served_images.hpp, the same code),
// with the actuator the editor designs for. A window shows the URL and its QR code; each save
// (Ctrl+S) reaches the open pages. The server stops with "Stop", a new audition, or the editor.
//
// Threads: everything here on the GUI thread; the server and its watcher run on their own threads,
// and their messages (a save that does not compile) go to stderr and to the window's last line
// under a mutex.
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "editor/notices.hpp"
#include "web/server/served_images.hpp"
#include "web/server/terminal_qr.hpp"

namespace vimg::editor {

class AuditionWindow {
 public:
  explicit AuditionWindow(Notices& notices) : notices_(notices) {}
  ~AuditionWindow();
  AuditionWindow(const AuditionWindow&) = delete;
  AuditionWindow& operator=(const AuditionWindow&) = delete;

  // Serves `image` (a saved file) with the actuator profile at `actuator_profile` (empty: ideal).
  void start(const std::filesystem::path& image, const std::string& actuator_profile);
  void stop();
  bool serving() const { return served_ != nullptr; }
  void draw(float x, float y);

 private:
  void message(const std::string& line);

  Notices& notices_;
  std::unique_ptr<web::ServedImages> served_;
  std::filesystem::path image_;
  std::string url_;
  std::optional<web::QrModules> qr_;
  mutable std::mutex message_mutex_;
  std::string last_message_;
};

}  // namespace vimg::editor
