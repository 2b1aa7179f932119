// `vimg import`: the written files pass `vimg validate`, and the command follows the project's
// conventions (--help 0, usage errors 2, bad input 1 with FILE: error).
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "png_fixture.hpp"
#include "tests/cli/run_command.hpp"

namespace vimg {
namespace {

using test::CommandRun;

CommandRun vimg(const std::string& args) { return test::run_command("'" VIMG_BINARY_DIR "/cli/vimg' " + args); }

class ImportCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("vimg_import_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return "'" + (dir_ / name).string() + "'"; }
  void write(const std::string& name, const std::string& bytes) const {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
  }
  std::filesystem::path dir_;
};

TEST_F(ImportCommand, ImportedDrawingsAndPicturesPassValidate) {
  const std::string svg = "'" VIMG_SOURCE_DIR "/tests/import/data/adwaita-parental-controls.svg'";
  CommandRun r = vimg("import " + svg + " --out " + path("icon.vimg"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = vimg("validate " + path("icon.vimg"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find(": ok"), std::string::npos);

  std::vector<std::uint8_t> px(20 * 10, 255);
  for (int y = 2; y < 8; ++y) for (int x = 5; x < 15; ++x) px[static_cast<std::size_t>(y * 20 + x)] = 0;
  write("square.png", test::make_png(20, 10, 1, px));
  r = vimg("import " + path("square.png") + " --out " + path("square.png.vimg") + " --width-mm 40 --levels 2");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = vimg("validate " + path("square.png.vimg"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  // Written as a PNG vibroimage too.
  r = vimg("import " + path("square.png") + " --out " + path("square_vimg.png") + " --width-mm 40");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(vimg("validate " + path("square_vimg.png")).exit_code, 0);
  // Importing that PNG again opens it: it already is a vibroimage.
  r = vimg("import " + path("square_vimg.png") + " --out " + path("again.vimg") + " --width-mm 40");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("opened as one, not imported"), std::string::npos) << r.out;
}

TEST_F(ImportCommand, FollowsTheCommandLineConventions) {
  EXPECT_EQ(vimg("import --help").exit_code, 0);
  EXPECT_EQ(vimg("import x.svg").exit_code, 2);  // --out missing
  EXPECT_EQ(vimg("import x.png --out y.vimg --levels 0").exit_code, 2);
  EXPECT_EQ(vimg("import x.png --out y.vimg --width-mm nan").exit_code, 2);
  write("bad.svg", "<svg width='10mm' height='10mm'>\n<rect");
  CommandRun r = vimg("import " + path("bad.svg") + " --out " + path("bad.vimg"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("bad.svg:2: error:"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.vimg"));
  write("p.png", test::make_png(2, 2, 1, {0, 0, 0, 0}));
  r = vimg("import " + path("p.png") + " --out " + path("p.vimg"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("p.png: error: a picture needs the width"), std::string::npos) << r.out;
  write("n.txt", "x");
  EXPECT_EQ(vimg("import " + path("n.txt") + " --out " + path("n.vimg")).exit_code, 1);
}

// PNG specification, 11.2.2 IHDR: "Zero is an invalid value" for the width and for the height. A
// header that gives one is refused by name, by every command that reads a PNG, before its image
// data is looked at (it used to be refused for inflating past the 0 bytes its 0 rows need).
TEST_F(ImportCommand, APngWithAZeroWidthOrHeightIsRefusedForWhatPngForbids) {
  const struct {
    const char* name;
    int width, height;
    const char* gives;
  } cases[] = {{"no-width.png", 0, 10, "a width of 0"}, {"no-height.png", 10, 0, "a height of 0"}, {"none.png", 0, 0, "a width and a height of 0"}};
  for (const auto& c : cases) {
    write(c.name, test::make_png(c.width, c.height, 1, {}));
    const std::string expected = std::string(c.name) + ": error: the PNG header gives " + c.gives +
                                 "; PNG requires a width and height of at least 1\n";
    for (const std::string& command : {"validate " + path(c.name), "info " + path(c.name),
                                      "import " + path(c.name) + " --out " + path("out.vimg") + " --width-mm 40"}) {
      const CommandRun r = vimg(command);
      EXPECT_EQ(r.exit_code, 1) << command << "\n" << r.out;
      EXPECT_NE(r.out.find(expected), std::string::npos) << command << "\n" << r.out;
      EXPECT_EQ(r.out.find("inflates"), std::string::npos) << command << "\n" << r.out;
      EXPECT_FALSE(std::filesystem::exists(dir_ / "out.vimg"));
    }
  }
}

// Runs `vimg import INPUT --out OUTPUT ...` and sends `signal_number` when the program shows that the
// import is under way: it has read its input (inotify: the file was closed after reading). The
// exit status, or -1.
int import_and_signal_once_read(const std::filesystem::path& input, const std::filesystem::path& output, int signal_number) {
  const int watch = inotify_init1(IN_CLOEXEC);
  if (watch < 0 || inotify_add_watch(watch, input.c_str(), IN_CLOSE_NOWRITE) < 0) return -1;
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl(VIMG_BINARY_DIR "/cli/vimg", "vimg", "import", input.c_str(), "--out", output.c_str(), "--width-mm", "100",
            "--levels", "16", static_cast<char*>(nullptr));
    _exit(127);
  }
  if (pid < 0) {  // never signalled: kill(-1, ...) would reach every process of the user
    ::close(watch);
    return -1;
  }
  pollfd p{watch, POLLIN, 0};
  if (::poll(&p, 1, 60000) > 0) ::kill(pid, signal_number);
  ::close(watch);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST_F(ImportCommand, SigintAndSigtermWriteNothingAndExit130And143) {
  // A picture whose tracing takes a while after the file is read (16 levels of a fine diagonal
  // pattern), so that the signal, sent once the input has been read, lands during the import.
  const int w = 300, h = 250;
  std::vector<std::uint8_t> px(static_cast<std::size_t>(w * h));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) px[static_cast<std::size_t>(y * w + x)] = static_cast<std::uint8_t>((x * 7 + y * 13) % 256);
  }
  write("big.png", test::make_png(w, h, 1, px));
  for (const auto& [signal_number, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
    EXPECT_EQ(import_and_signal_once_read(dir_ / "big.png", dir_ / "big.vimg", signal_number), code) << signal_number;
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename(), "big.png") << "left behind: " << entry.path();
  }
}

}  // namespace
}  // namespace vimg
