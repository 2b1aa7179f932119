#pragma once
// Watches image files for saves (inotify) and calls back, from a thread of its own, with the path
// of each image that changed. It watches each image's folder, not the file: editors and
// storage/atomic_file.hpp save by writing a temporary and renaming it over the image, which
// replaces the file (a watch on the file would see its old inode go and nothing after). A save is
// a rename onto the image's name (IN_MOVED_TO) or a write of the file in place that ends
// (IN_CLOSE_WRITE). An image named through a symbolic link is watched in its target's folder too.
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace vimg::web {

class ImageWatcher {
 public:
  using OnSave = std::function<void(const std::filesystem::path& image)>;

  // Starts watching; `on_save` runs on the watcher's thread, one save at a time.
  ImageWatcher(const std::vector<std::filesystem::path>& images, OnSave on_save);
  ~ImageWatcher();  // stops and joins the thread
  ImageWatcher(const ImageWatcher&) = delete;
  ImageWatcher& operator=(const ImageWatcher&) = delete;

  // Why watching could not start (no inotify, a folder that cannot be watched); empty when it runs.
  const std::string& error() const { return error_; }

 private:
  void run();
  void handle_events(const char* buffer, long length);

  struct Watched {
    std::string file_name;          // the name in the watched folder
    std::filesystem::path image;    // the image as the caller named it
  };
  OnSave on_save_;
  int inotify_fd_ = -1;
  int stop_fd_ = -1;  // an eventfd the destructor writes to wake the thread
  std::map<int, std::vector<Watched>> by_watch_;
  std::string error_;
  std::thread thread_;
};

}  // namespace vimg::web
