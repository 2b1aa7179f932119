#include "web/server/image_watcher.hpp"

#include <poll.h>
#include <sys/eventfd.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <set>

namespace vimg::web {

namespace fs = std::filesystem;

namespace {

constexpr std::uint32_t kSaveEvents = IN_CLOSE_WRITE | IN_MOVED_TO;

}  // namespace

ImageWatcher::ImageWatcher(const std::vector<fs::path>& images, OnSave on_save) : on_save_(std::move(on_save)) {
  inotify_fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  stop_fd_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (inotify_fd_ < 0 || stop_fd_ < 0) {
    error_ = std::string("cannot watch the images: ") + std::strerror(errno);
    return;
  }
  for (const fs::path& image : images) {
    std::error_code ec;
    std::set<fs::path> names{fs::absolute(image, ec)};
    const fs::path target = fs::weakly_canonical(image, ec);
    if (!ec) names.insert(target);
    for (const fs::path& name : names) {
      const fs::path folder = name.parent_path();
      const int wd = inotify_add_watch(inotify_fd_, folder.c_str(), kSaveEvents | IN_ONLYDIR);
      if (wd < 0) {
        error_ = folder.string() + ": cannot watch this folder: " + std::strerror(errno);
        return;
      }
      by_watch_[wd].push_back({name.filename().string(), image});
    }
  }
  thread_ = std::thread([this] { run(); });
}

ImageWatcher::~ImageWatcher() {
  if (thread_.joinable()) {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t written = write(stop_fd_, &one, sizeof one);
    thread_.join();
  }
  if (inotify_fd_ >= 0) close(inotify_fd_);
  if (stop_fd_ >= 0) close(stop_fd_);
}

void ImageWatcher::run() {
  alignas(inotify_event) char buffer[16 * 1024];
  pollfd fds[2] = {{inotify_fd_, POLLIN, 0}, {stop_fd_, POLLIN, 0}};
  while (true) {
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      return;
    }
    if (fds[1].revents != 0) return;
    if (fds[0].revents == 0) continue;
    const ssize_t n = read(inotify_fd_, buffer, sizeof buffer);
    if (n > 0) handle_events(buffer, static_cast<long>(n));
  }
}

void ImageWatcher::handle_events(const char* buffer, long length) {
  std::set<fs::path> saved;  // one call per image however many events one read holds
  std::vector<fs::path> order;
  for (long offset = 0; offset + static_cast<long>(sizeof(inotify_event)) <= length;) {
    inotify_event event;
    std::memcpy(&event, buffer + offset, sizeof event);
    const char* name = buffer + offset + sizeof(inotify_event);
    offset += static_cast<long>(sizeof(inotify_event) + event.len);
    if (event.len == 0 || (event.mask & kSaveEvents) == 0) continue;
    const auto watched = by_watch_.find(event.wd);
    if (watched == by_watch_.end()) continue;
    for (const Watched& w : watched->second) {
      if (w.file_name == name && saved.insert(w.image).second) order.push_back(w.image);
    }
  }
  for (const fs::path& image : order) on_save_(image);
}

}  // namespace vimg::web
