// `vimg convert` killed by SIGINT or SIGTERM while it writes its output: it exits 130/143 and
// leaves no temporary (AtomicFileWriter's registry, emptied by the handler vimg's main installs)
// and no output. The signal is sent the moment the temporary appears in the folder (inotify), so
// it lands during the write and fsync of a large output. A PNG output is also interrupted while
// its threads draw and compress, before any file exists: the signal is sent once a second thread
// of the process runs (/proc/PID/task), never after a fixed time.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

// 200 000 dots on a 300 x 300 mm canvas: about 9 MB of XML in, the same out.
void write_big_image(const fs::path& path) {
  std::ofstream out(path);
  out << "<vibroimage version=\"1.0\" width=\"300\" height=\"300\">\n";
  for (int i = 0; i < 200000; ++i) {
    out << "<dot id=\"d" << i << "\" x=\"" << (i % 290) + 0.123456 << "\" y=\"" << (i / 290) % 290 + 0.654321
        << "\" radius=\"1.25\" gain=\"0.5\"/>\n";
  }
  out << "</vibroimage>\n";
}

struct Outcome {
  bool signalled_mid_write = false;  // the state was seen when the signal was sent
  int status = 0;
};

// The threads of process `pid` (/proc/PID/task), 0 once it has gone.
int threads_of(pid_t pid) {
  std::error_code ec;
  int n = 0;
  for (fs::directory_iterator it("/proc/" + std::to_string(pid) + "/task", ec), end; !ec && it != end; it.increment(ec)) ++n;
  return n;
}

enum class SignalWhen { temporary_appears, threads_work };

// Converts in.vimg to `out_name` and sends `signal_number` when the program shows the state: the
// temporary of `out_name` appears in the folder (inotify), or more than one of its threads runs
// (a PNG's drawing and compression, before any file exists).
Outcome convert_and_signal(const fs::path& dir, int signal_number, const std::string& out_name = "out.vimg",
                           SignalWhen when = SignalWhen::temporary_appears) {
  Outcome outcome;
  const int watch_fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  EXPECT_GE(watch_fd, 0);
  inotify_add_watch(watch_fd, dir.c_str(), IN_CREATE);
  const std::string in = (dir / "in.vimg").string(), out = (dir / out_name).string();  // made before the fork
  const pid_t pid = fork();
  if (pid == 0) {
    execl(kVimg.c_str(), "vimg", "convert", in.c_str(), out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  EXPECT_GT(pid, 0) << "fork failed";
  if (pid < 0) {  // never signalled: kill(-1, ...) would reach every process of the user
    close(watch_fd);
    return outcome;
  }
  if (when == SignalWhen::threads_work) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (threads_of(pid) < 2 && std::chrono::steady_clock::now() < give_up) usleep(50);
    outcome.signalled_mid_write = threads_of(pid) >= 2;  // here: while its threads worked
    kill(pid, signal_number);
    close(watch_fd);
    waitpid(pid, &outcome.status, 0);
    return outcome;
  }
  alignas(inotify_event) char buffer[4096];
  pollfd p{watch_fd, POLLIN, 0};
  while (!outcome.signalled_mid_write && poll(&p, 1, 60000) > 0) {
    const ssize_t n = read(watch_fd, buffer, sizeof buffer);
    for (ssize_t off = 0; off < n;) {
      const auto* e = reinterpret_cast<const inotify_event*>(buffer + off);
      if (e->len > 0 && std::string(e->name).starts_with("." + out_name + ".tmp-")) {
        kill(pid, signal_number);
        outcome.signalled_mid_write = true;
        break;
      }
      off += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
    }
  }
  close(watch_fd);
  waitpid(pid, &outcome.status, 0);
  return outcome;
}

TEST(ConvertInterrupt, ASignalMidWriteLeavesNoTemporaryAndExits130Or143) {
  const fs::path dir = fs::path(VIMG_BINARY_DIR) / "hostile_convert_interrupt";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_big_image(dir / "in.vimg");
  for (const auto& [signal_number, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
    const Outcome o = convert_and_signal(dir, signal_number);
    ASSERT_TRUE(o.signalled_mid_write) << "the temporary never appeared";
    ASSERT_TRUE(WIFEXITED(o.status)) << "signal " << signal_number << " killed vimg without its handler";
    EXPECT_EQ(WEXITSTATUS(o.status), code);
    EXPECT_EQ(names_in(dir), std::vector<std::string>{"in.vimg"}) << "signal " << signal_number;
  }
}

TEST(ConvertInterrupt, ASignalWhilePngThreadsWorkOrWriteLeavesNothingAndExits130Or143) {
  const fs::path dir = fs::path(VIMG_BINARY_DIR) / "hostile_convert_interrupt_png";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_big_image(dir / "in.vimg");
  for (const auto& [signal_number, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
    // While the file is written: the temporary exists.
    const Outcome writing = convert_and_signal(dir, signal_number, "out.png");
    ASSERT_TRUE(writing.signalled_mid_write) << "the temporary never appeared";
    ASSERT_TRUE(WIFEXITED(writing.status)) << "signal " << signal_number << " killed vimg without its handler";
    EXPECT_EQ(WEXITSTATUS(writing.status), code);
    EXPECT_EQ(names_in(dir), std::vector<std::string>{"in.vimg"}) << "signal " << signal_number;
    // While its threads draw and compress.
    const Outcome encoding = convert_and_signal(dir, signal_number, "out.png", SignalWhen::threads_work);
    ASSERT_TRUE(encoding.signalled_mid_write) << "no second thread ever ran";
    ASSERT_TRUE(WIFEXITED(encoding.status)) << "signal " << signal_number << " killed vimg without its handler";
    EXPECT_EQ(WEXITSTATUS(encoding.status), code);
    EXPECT_EQ(names_in(dir), std::vector<std::string>{"in.vimg"}) << "signal " << signal_number;
  }
}

}  // namespace
