// `vimg serve IMAGE` when a save does not compile (docs/web-serving.md, "Serving": "A save that does not
// compile prints its FILE:LINE: error: lines and the pages keep the last good scene"): the errors
// are printed, the site's .vsc is still the last good one, and no open page is told of a change
// (a good save of another image, later in the same stream, is the first event the page gets); the
// next good save of the image reaches the page with its new scene. Over real sockets, with the real
// program; every wait is for a line printed or an event received.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "storage/atomic_file.hpp"
#include "tests/net/raw_http.hpp"
#include "tests/web_server/serve_output.hpp"

namespace vimg::test {
namespace {

namespace fs = std::filesystem;

TEST(ServeBadSave, ASaveThatDoesNotCompileKeepsTheLastGoodSceneOnTheOpenPages) {
  const fs::path dir = fs::path(VIMG_BINARY_DIR) / "web_server_tests" / "ServeBadSave";
  fs::remove_all(dir);
  write_stand_in_assets(dir / "assets");
  const fs::path image = dir / "smiley.vimg";
  const fs::path other = dir / "other.vimg";  // a second image, whose good save marks a point in the stream
  fs::copy_file(fs::path(VIMG_SOURCE_DIR) / "assets/examples/smiley.vimg", image);
  fs::copy_file(fs::path(VIMG_SOURCE_DIR) / "assets/examples/set_a2_two_objects.vimg", other);
  ServeOutput serve({image.string(), other.string()}, dir);
  const int port = serve.wait_for_port();
  ASSERT_GT(port, 0) << serve.out() << serve.err();
  const HttpResponse good = exchange(port, "GET", "/images/smiley.vsc");
  ASSERT_EQ(good.status, 200);
  ASSERT_FALSE(good.body.empty());
  RawConnection page(port);
  page.send_all("GET /events HTTP/1.1\r\nHost: localhost\r\n\r\n");
  ASSERT_TRUE(page.read_until(": connected\n")) << page.received();

  // Two saves that do not compile, each with a bad attribute (at line 2, then at line 4).
  ASSERT_FALSE(write_file_atomically(image, "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n<dot x=\"oops\"/>\n</vibroimage>\n"));
  ASSERT_TRUE(serve.wait_for_err(image.string() + ":2: error:")) << serve.err();
  EXPECT_EQ(exchange(port, "GET", "/images/smiley.vsc").body, good.body);
  ASSERT_FALSE(write_file_atomically(image, "<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n\n\n<dot x=\"1\" y=\"nope\"/>\n</vibroimage>\n"));
  ASSERT_TRUE(serve.wait_for_err(image.string() + ":4: error:")) << serve.err();
  EXPECT_EQ(exchange(port, "GET", "/images/smiley.vsc").body, good.body);
  EXPECT_EQ(serve.err().find("changed: pushed to the open pages"), std::string::npos) << serve.err();
  // The other image's good save comes after both in the page's stream (one stream, in order): every
  // event the bad saves could have sent is before it, and there is none.
  ASSERT_FALSE(write_file_atomically(other, file_text(fs::path(VIMG_SOURCE_DIR) / "assets/examples/smiley.vimg")));
  ASSERT_TRUE(page.read_until("event: image\ndata: other\n\n")) << page.received();
  EXPECT_EQ(page.count_of("event: "), 1) << page.received();
  EXPECT_EQ(page.count_of("data: smiley"), 0) << page.received();
  EXPECT_EQ(exchange(port, "GET", "/images/smiley.vsc").body, good.body);

  // A good save of the image reaches the page, with its new scene.
  const std::string saved = file_text(fs::path(VIMG_SOURCE_DIR) / "assets/examples/set_a2_two_objects.vimg");
  ASSERT_FALSE(write_file_atomically(image, saved));
  ASSERT_TRUE(page.read_until("event: image\ndata: smiley\n\n")) << page.received();
  EXPECT_EQ(page.count_of("event: "), 2) << page.received();
  const std::string after = exchange(port, "GET", "/images/smiley.vsc").body;
  EXPECT_NE(after, good.body);
  EXPECT_EQ(serve.stop_with(SIGINT), 130);
}

}  // namespace
}  // namespace vimg::test
