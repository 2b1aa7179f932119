// The read-only server of a built site over real sockets (docs/web-serving.md, "Serving"): the site's
// files with their types, and every way out of the folder, every method but GET and HEAD, every
// listing and every oversized request refused. Requests are sent byte for byte (raw_http.hpp).
#include <gtest/gtest.h>

#include <string>

#include "tests/net/raw_http.hpp"
#include "tests/web_server/site_fixture.hpp"

namespace vimg::test {
namespace {

using StaticServer = SiteFixture;

TEST_F(StaticServer, ServesTheSiteFilesWithTheirTypesAndNoStore) {
  start_server();
  HttpResponse root = exchange(port(), "GET", "/");
  EXPECT_EQ(root.status, 200);
  EXPECT_EQ(root.body, "<!doctype html><title>site</title>");
  EXPECT_EQ(root.headers["content-type"], "text/html; charset=utf-8");
  EXPECT_EQ(root.headers["cache-control"], "no-store");
  EXPECT_EQ(root.headers["x-content-type-options"], "nosniff");
  EXPECT_EQ(exchange(port(), "GET", "/vimg.wasm").headers["content-type"], "application/wasm");
  EXPECT_EQ(exchange(port(), "GET", "/vimg.js").headers["content-type"], "text/javascript; charset=utf-8");
  EXPECT_EQ(exchange(port(), "GET", "/images/index.json").headers["content-type"], "application/json");
  HttpResponse vsc = exchange(port(), "GET", "/images/smiley.vsc");
  EXPECT_EQ(vsc.status, 200);
  EXPECT_EQ(vsc.body, "VSC1");
  EXPECT_EQ(vsc.headers["content-type"], "application/octet-stream");
  // A symbolic link that stays inside the site is followed.
  EXPECT_EQ(exchange(port(), "GET", "/link_in.html").status, 200);
}

TEST_F(StaticServer, HeadGivesTheHeadersWithoutTheBody) {
  start_server();
  HttpResponse head = exchange(port(), "HEAD", "/images/smiley.vsc");
  EXPECT_EQ(head.status, 200);
  EXPECT_EQ(head.headers["content-length"], "4");
  EXPECT_EQ(head.body, "");
}

TEST_F(StaticServer, TraversalIsRefusedPlainOrPercentEncoded) {
  start_server();
  for (const std::string target : {"/../secret.txt", "/images/../../secret.txt", "/%2e%2e/secret.txt",
                                   "/%2E%2E/secret.txt", "/images/%2e%2e/%2e%2e/secret.txt", "/..%2fsecret.txt",
                                   "/.%2e/secret.txt", "/images/..", "/%2e%2e"}) {
    HttpResponse r = exchange(port(), "GET", target);
    EXPECT_EQ(r.status, 403) << target;
    EXPECT_EQ(r.body.find("the secret"), std::string::npos) << target;
  }
}

TEST_F(StaticServer, SymbolicLinksOutOfTheSiteAreRefused) {
  start_server();
  for (const std::string target : {"/link_out.txt", "/folder_out/secret.txt", "/folder_out/"}) {
    HttpResponse r = exchange(port(), "GET", target);
    EXPECT_EQ(r.status, 403) << target;
    EXPECT_EQ(r.body.find("the secret"), std::string::npos) << target;
  }
}

TEST_F(StaticServer, OtherMethodsGet405WithAllow) {
  start_server();
  for (const std::string method : {"POST", "PUT", "DELETE", "PATCH", "OPTIONS"}) {
    HttpResponse r = exchange(port(), method, "/index.html", "Content-Length: 5\r\n", "hello");
    EXPECT_EQ(r.status, 405) << method;
    EXPECT_EQ(r.headers["allow"], "GET, HEAD") << method;
  }
  EXPECT_EQ(exchange(port(), "PUT", "/new.html", "Content-Length: 5\r\n", "hello").status, 405);
  EXPECT_FALSE(fs::exists(site_ / "new.html"));
}

TEST_F(StaticServer, NoListingAndUnknownFilesAreNotFound) {
  start_server();
  HttpResponse empty = exchange(port(), "GET", "/empty/");
  EXPECT_EQ(empty.status, 404);
  EXPECT_EQ(empty.body.find("index"), std::string::npos);
  EXPECT_EQ(exchange(port(), "GET", "/images/").status, 404);
  EXPECT_EQ(exchange(port(), "GET", "/images").status, 404);
  EXPECT_EQ(exchange(port(), "GET", "/no-such-file.html").status, 404);
  EXPECT_EQ(exchange(port(), "GET", "/images/no-such.vsc").status, 404);
}

TEST_F(StaticServer, HiddenFilesAndTemporariesAreNotServed) {
  write_text(site_ / "images" / ".smiley.vsc.tmp-123", "half written");
  start_server();
  EXPECT_EQ(exchange(port(), "GET", "/images/.smiley.vsc.tmp-123").status, 404);
}

TEST_F(StaticServer, OversizedRequestsAreRefused) {
  start_server();
  // A request line (URI) beyond the 8 KiB the library allows.
  EXPECT_EQ(exchange(port(), "GET", "/" + std::string(9000, 'a')).status, 414);
  // A header line beyond 8 KiB.
  HttpResponse long_header = exchange(port(), "GET", "/index.html", "X-Long: " + std::string(9000, 'b') + "\r\n");
  EXPECT_EQ(long_header.status, 400);
  // A body is never read: a request that announces 1 GB (and sends none of it) is answered at once
  // (405), where a server reading it would wait for the bytes, then time out with another status.
  EXPECT_EQ(exchange(port(), "POST", "/index.html", "Content-Length: 1000000000\r\n").status, 405);
  EXPECT_EQ(exchange(port(), "PUT", "/index.html", "Transfer-Encoding: chunked\r\n").status, 405);
}

TEST_F(StaticServer, LogsOneLinePerRequestWithMethodPathStatusAndBytes) {
  start_server();
  exchange(port(), "GET", "/images/smiley.vsc");
  exchange(port(), "POST", "/x", "Content-Length: 0\r\n");
  exchange(port(), "GET", "/a%0aforged%20200%201");
  server_->stop();  // the log of every finished request is written
  const std::vector<std::string> lines = log();
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "GET /images/smiley.vsc 200 4");
  EXPECT_EQ(lines[1].substr(0, 12), "POST /x 405 ");
  EXPECT_EQ(lines[2].rfind("GET /a\\x0aforged 200 1 404 ", 0), 0u) << lines[2];  // the newline cannot forge a line
}

}  // namespace
}  // namespace vimg::test
