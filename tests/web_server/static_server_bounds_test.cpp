// The static server's refusals that docs/web-serving.md ("Serving") promises beyond the way out of the folder:
// a NUL or a backslash in the path (plain or percent-encoded) is forbidden (403); a FIFO or a device
// in the site, or linked into it, is never opened for reading (404, or 403 for a link out of the
// site), so a request for one can neither hang a worker on a FIFO without a writer nor stream
// /dev/zero forever; and a file is served up to kMaxServedFileBytes (64 MiB), not a byte beyond.
// Over real sockets (raw_http.hpp); each exchange ends when the server closes the connection, and
// the hang bound of raw_http.hpp only ends a hang.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "tests/net/raw_http.hpp"
#include "tests/web_server/site_fixture.hpp"

namespace vimg::test {
namespace {

using StaticServerBounds = SiteFixture;
using web::kMaxServedFileBytes;

// One request whose answer must come, and the connection close, well before the hang bound: a
// worker stuck on a FIFO or streaming a device would run into it.
HttpResponse answered(int port, const std::string& target) {
  RawConnection connection(port);
  EXPECT_TRUE(connection.connected());
  connection.send_all("GET " + target + " HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n");
  EXPECT_TRUE(connection.read_to_end(std::chrono::seconds(20))) << target << ": the server did not close";
  EXPECT_LT(connection.received().size(), std::size_t{1} << 20) << target;
  return parse_response(connection.received());
}

TEST_F(StaticServerBounds, ANulOrABackslashInThePathIsForbidden) {
  write_text(site_ / "images" / "a\\b.vsc", "behind a backslash");
  start_server();
  for (const std::string target : {"/index.html%00", "/index.html%00.png", "/%00", "/images%00/smiley.vsc",
                                   "/images%5csmiley.vsc", "/images%5Csmiley.vsc", "/images\\smiley.vsc",
                                   "/images/a%5cb.vsc", "/images/a\\b.vsc", "/%5c..%5csecret.txt"}) {
    const HttpResponse r = answered(port(), target);
    EXPECT_EQ(r.status, 403) << target;
    EXPECT_EQ(r.body.rfind("forbidden: ", 0), 0u) << target << ": " << r.body;
  }
  // The same files by their plain names are served: the refusal is the character's.
  EXPECT_EQ(answered(port(), "/index.html").status, 200);
  EXPECT_EQ(answered(port(), "/images/smiley.vsc").status, 200);
}

TEST_F(StaticServerBounds, FifosAndDevicesAreNeverRead) {
  ASSERT_EQ(::mkfifo((site_ / "pipe.vsc").c_str(), 0644), 0) << std::strerror(errno);
  fs::create_symlink("pipe.vsc", site_ / "images" / "to_pipe.vsc");  // resolves inside the site
  fs::create_symlink("/dev/zero", site_ / "zero.vsc");                  // a device out of the site
  fs::create_symlink("/dev", site_ / "dev");
  start_server();
  EXPECT_EQ(answered(port(), "/pipe.vsc").status, 404);
  EXPECT_EQ(answered(port(), "/images/to_pipe.vsc").status, 404);
  EXPECT_EQ(answered(port(), "/zero.vsc").status, 403);
  EXPECT_EQ(answered(port(), "/dev/zero").status, 403);
  EXPECT_EQ(answered(port(), "/dev/urandom").status, 403);
  // The FIFO was never opened: a reader would have waited for a writer, and a writer opening it
  // without blocking now finds no reader.
  const int writer = ::open((site_ / "pipe.vsc").c_str(), O_WRONLY | O_NONBLOCK);
  EXPECT_EQ(writer, -1);
  EXPECT_EQ(errno, ENXIO);
  if (writer >= 0) ::close(writer);
  // Every refusal was logged with its status; the server still serves.
  EXPECT_EQ(answered(port(), "/index.html").status, 200);
}

// A device node of /dev/zero inside the site itself. Making one needs CAP_MKNOD (root; CI runs as
// root and runs this case); without it the case is reported as skipped, with the reason, never as
// a pass.
TEST_F(StaticServerBounds, ADeviceNodeInsideTheSiteIsNeverRead) {
  if (::mknod((site_ / "zero_here.vsc").c_str(), S_IFCHR | 0644, makedev(1, 5)) != 0) {
    GTEST_SKIP() << "cannot make a device node in the site (" << std::strerror(errno)
                 << "): needs CAP_MKNOD, i.e. root";
  }
  start_server();
  EXPECT_EQ(answered(port(), "/zero_here.vsc").status, 404);
  EXPECT_EQ(answered(port(), "/index.html").status, 200);
}

TEST_F(StaticServerBounds, AFileIsServedUpTo64MiBAndNotAByteMore) {
  ASSERT_EQ(kMaxServedFileBytes, std::size_t{64} << 20);  // the bound docs/web-serving.md names
  // Sparse files: the bound is on the size, whatever the disk holds.
  { std::ofstream(site_ / "at_bound.vsc"); }
  { std::ofstream(site_ / "past_bound.vsc"); }
  fs::resize_file(site_ / "at_bound.vsc", kMaxServedFileBytes);
  fs::resize_file(site_ / "past_bound.vsc", kMaxServedFileBytes + 1);
  start_server();
  HttpResponse at = exchange(port(), "HEAD", "/at_bound.vsc");
  EXPECT_EQ(at.status, 200);
  EXPECT_EQ(at.headers["content-length"], std::to_string(kMaxServedFileBytes));
  const HttpResponse past = answered(port(), "/past_bound.vsc");
  EXPECT_EQ(past.status, 500);
  EXPECT_EQ(past.body.size() < 4096 ? past.body : std::to_string(past.body.size()) + " bytes", "the file cannot be read\n");
  EXPECT_EQ(exchange(port(), "HEAD", "/past_bound.vsc").status, 500);
  server_->stop();
  bool said_why = false;
  for (const std::string& line : log()) said_why = said_why || line.find("past_bound.vsc") != std::string::npos;
  EXPECT_TRUE(said_why);
}

}  // namespace
}  // namespace vimg::test
