// `vimg serve` and `vimg web` as processes (docs/web-serving.md, "Serving"): the URL printed once the server
// listens; a save of an image (an atomic rename) reaches an open page as an "image" event after
// the site's .vsc was rewritten (it is then the .vsc `vimg web` writes for the saved image);
// SIGINT/SIGTERM after the URL end it with 130/143 and remove the temporary site; usage errors 2,
// bad images 1 with FILE:LINE: error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "storage/atomic_file.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/net/raw_http.hpp"
#include "tests/web_server/serve_process.hpp"

namespace vimg::test {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

class ServeCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(VIMG_BINARY_DIR) / "web_server_tests" /
           (std::string("ServeCommand.") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "tmp");
    write_stand_in_assets(dir_ / "assets");
    fs::copy_file(fs::path(VIMG_SOURCE_DIR) / "assets/examples/smiley.vimg", dir_ / "smiley.vimg");
  }
  std::string env() const { return "VIMG_WEB_ASSETS='" + (dir_ / "assets").string() + "' "; }
  fs::path dir_;
};

TEST_F(ServeCommand, ASaveReachesTheOpenPageAfterItsVscIsRewritten) {
  ServeProcess serve({(dir_ / "smiley.vimg").string()}, dir_ / "assets", dir_ / "tmp");
  const int port = serve.wait_for_port();
  ASSERT_GT(port, 0) << serve.printed();
  const std::string before = exchange(port, "GET", "/images/smiley.vsc").body;
  ASSERT_FALSE(before.empty());
  RawConnection page(port);
  page.send_all("GET /events HTTP/1.1\r\nHost: localhost\r\n\r\n");
  ASSERT_TRUE(page.read_until(": connected\n")) << page.received();
  // The save: another image's content, renamed over smiley.vimg as editors and vimg save.
  const std::string saved = read_all(fs::path(VIMG_SOURCE_DIR) / "assets/examples/set_a2_two_objects.vimg");
  ASSERT_FALSE(write_file_atomically(dir_ / "smiley.vimg", saved));
  ASSERT_TRUE(page.read_until("event: image\ndata: smiley\n\n")) << page.received();
  // What the page fetches now is the .vsc of the saved image, as vimg web writes it.
  fs::create_directories(dir_ / "expected");
  fs::copy_file(dir_ / "smiley.vimg", dir_ / "expected" / "smiley.vimg");
  const CommandRun web = run_command(env() + kVimg + " web '" + (dir_ / "expected/smiley.vimg").string() + "' --out '" +
                                     (dir_ / "expected/site").string() + "'");
  ASSERT_EQ(web.exit_code, 0) << web.out;
  const std::string after = exchange(port, "GET", "/images/smiley.vsc").body;
  EXPECT_EQ(after, read_all(dir_ / "expected/site/images/smiley.vsc"));
  EXPECT_NE(after, before);
}

// The profile is read once, when vimg serve starts: a save compiles with it even after the profile
// file became unreadable (before, every save read and parsed it again, and this save failed).
TEST_F(ServeCommand, TheActuatorProfileIsReadOnceForEverySave) {
  fs::copy_file(fs::path(VIMG_SOURCE_DIR) / "assets/profiles/erm-10mm.xml", dir_ / "erm.xml");
  ServeProcess serve({(dir_ / "smiley.vimg").string(), "--actuator", (dir_ / "erm.xml").string()}, dir_ / "assets", dir_ / "tmp");
  const int port = serve.wait_for_port();
  ASSERT_GT(port, 0) << serve.printed();
  RawConnection page(port);
  page.send_all("GET /events HTTP/1.1\r\nHost: localhost\r\n\r\n");
  ASSERT_TRUE(page.read_until(": connected\n")) << page.received();
  ASSERT_FALSE(write_file_atomically(dir_ / "erm.xml", "<actuator name=\"broken\""));  // no longer a profile
  const std::string saved = read_all(fs::path(VIMG_SOURCE_DIR) / "assets/examples/set_a2_two_objects.vimg");
  ASSERT_FALSE(write_file_atomically(dir_ / "smiley.vimg", saved));
  ASSERT_TRUE(page.read_until("event: image\ndata: smiley\n\n")) << page.received();
  // The same .vsc as `vimg web` writes for the saved image with the profile as it was at the start.
  fs::create_directories(dir_ / "expected");
  fs::copy_file(dir_ / "smiley.vimg", dir_ / "expected" / "smiley.vimg");
  const CommandRun web = run_command(env() + kVimg + " web '" + (dir_ / "expected/smiley.vimg").string() +
                                     "' --actuator erm-10mm --out '" + (dir_ / "expected/site").string() + "'");
  ASSERT_EQ(web.exit_code, 0) << web.out;
  EXPECT_EQ(exchange(port, "GET", "/images/smiley.vsc").body, read_all(dir_ / "expected/site/images/smiley.vsc"));
}

TEST_F(ServeCommand, SigintAndSigtermExit130And143AndRemoveTheSite) {
  for (const auto& [signal_number, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
    ServeProcess serve({(dir_ / "smiley.vimg").string()}, dir_ / "assets", dir_ / "tmp");
    ASSERT_GT(serve.wait_for_port(), 0) << serve.printed();
    EXPECT_FALSE(fs::is_empty(dir_ / "tmp"));  // the site it serves
    EXPECT_EQ(serve.stop_with(signal_number), code) << "signal " << signal_number;
    EXPECT_TRUE(fs::is_empty(dir_ / "tmp")) << "signal " << signal_number;
  }
}

TEST_F(ServeCommand, ServesABuiltSiteFolder) {
  const CommandRun web = run_command(env() + kVimg + " web '" + (dir_ / "smiley.vimg").string() + "' --out '" +
                                     (dir_ / "site").string() + "'");
  ASSERT_EQ(web.exit_code, 0) << web.out;
  ServeProcess serve({(dir_ / "site").string()}, dir_ / "assets", dir_ / "tmp");
  const int port = serve.wait_for_port();
  ASSERT_GT(port, 0) << serve.printed();
  EXPECT_EQ(exchange(port, "GET", "/").body, "stand-in index.html\n");
  EXPECT_EQ(exchange(port, "GET", "/images/smiley.vsc").body, read_all(dir_ / "site/images/smiley.vsc"));
  EXPECT_EQ(serve.stop_with(SIGINT), 130);
}

TEST_F(ServeCommand, UsageErrorsExit2AndBadInputs1) {
  const std::string image = "'" + (dir_ / "smiley.vimg").native() + "'";  // not .string(): GCC 12's -O3 -Wstringop-overflow misfires on it
  EXPECT_EQ(run_command(kVimg + " serve --help").exit_code, 0);
  EXPECT_EQ(run_command(kVimg + " web --help").exit_code, 0);
  EXPECT_EQ(run_command(kVimg + " serve").exit_code, 2);
  EXPECT_EQ(run_command(kVimg + " serve " + image + " --port 70000").exit_code, 2);
  EXPECT_EQ(run_command(kVimg + " serve '" + dir_.string() + "' " + image).exit_code, 2);  // a folder among images
  EXPECT_EQ(run_command(kVimg + " web " + image).exit_code, 2);                            // no --out
  // A folder that is not a built site, and an image that does not load.
  EXPECT_EQ(run_command(kVimg + " serve '" + (dir_ / "tmp").string() + "'").exit_code, 1);
  std::ofstream(dir_ / "bad.vimg") << "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n<dot x=\"oops\"/>\n";
  const CommandRun bad = run_command(env() + kVimg + " serve '" + (dir_ / "bad.vimg").string() + "' --port 0");
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
  EXPECT_NE(bad.out.find("bad.vimg:2: error:"), std::string::npos) << bad.out;
}

}  // namespace
}  // namespace vimg::test
