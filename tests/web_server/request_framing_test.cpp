// How the server reads a request's framing (docs/web-serving.md, "Connections"): a whole header over
// 16 KiB, a chunked body over the 4 KiB limit, Expect: 100-continue, pipelined requests, and the
// framings a proxy could read otherwise (Content-Length with Transfer-Encoding, Content-Length
// twice or as a list, a transfer coding other than chunked), each refused with 400. Each test says
// how it was seen to fail against a server broken on purpose.
#include <gtest/gtest.h>

#include <string>

#include "tests/net/raw_http.hpp"
#include "tests/web_server/site_fixture.hpp"
#include "tests/web_server/stub_api.hpp"
#include "web/server/http_message.hpp"

namespace vimg::test {
namespace {

using RequestFraming = SiteFixture;

HttpResponse send_raw(int port, const std::string& bytes) {
  RawConnection connection(port);
  if (!connection.connected() || !connection.send_all(bytes)) return {};
  connection.read_to_end();
  return parse_response(connection.received());
}

// Every header line under 8 KiB, the whole over 16 KiB: 400. Seen to fail (200) with
// header_limit raised to 64 KiB in Session::read_header (and the buffer with it).
TEST_F(RequestFraming, AWholeHeaderOver16KiBIs400) {
  start_server();
  std::string lines;
  for (int i = 0; lines.size() <= web::kMaxHeaderBytes; ++i) lines += "X-Filler-" + std::to_string(i) + ": " + std::string(1000, 'a') + "\r\n";
  EXPECT_EQ(send_raw(port(), "GET /index.html HTTP/1.1\r\nHost: localhost\r\n" + lines + "\r\n").status, 400);
  // Just under the bound, the same request is served.
  std::string under;
  for (int i = 0; under.size() + 1100 < web::kMaxHeaderBytes; ++i) under += "X-Filler-" + std::to_string(i) + ": " + std::string(1000, 'a') + "\r\n";
  EXPECT_EQ(send_raw(port(), "GET /index.html HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n" + under + "\r\n").status, 200);
}

std::string chunked(const std::string& body, std::size_t chunk_bytes) {
  std::string out;
  for (std::size_t at = 0; at < body.size(); at += chunk_bytes) out += web::format_chunk(std::string_view(body).substr(at, chunk_bytes));
  return out + "0\r\n\r\n";
}

// A chunked body, whose length no header announces, is cut at the 4 KiB limit: 413, the route
// never runs; one within the limit is read whole. Seen to fail (the route ran: 200) with
// body_limit left unlimited in Session::on_header.
TEST_F(RequestFraming, AChunkedBodyOverTheLimitIs413) {
  StubApi api(root_ / "answers.txt");
  start_server([&](WebServerOptions& options) { api.install(options); });
  api.disk.open();
  const std::string head = "POST /api/answer HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\nTransfer-Encoding: chunked\r\n\r\n";
  EXPECT_EQ(send_raw(port(), head + chunked(std::string(kMaxRequestBodyBytes + 1, 'a'), 1000)).status, 413);
  EXPECT_EQ(api.answers_synced, 0);
  EXPECT_EQ(send_raw(port(), head + chunked(std::string(kMaxRequestBodyBytes, 'a'), 1000)).status, 200);
  EXPECT_EQ(api.answers_synced, 1);
}

// Expect: 100-continue gets "100 Continue" before the body is sent, then the reply. Seen to fail
// (no 100 came: the test's read bound ended the wait) with the 100 Continue write removed.
TEST_F(RequestFraming, Expect100ContinueIsAnsweredBeforeTheBody) {
  StubApi api(root_ / "answers.txt");
  start_server([&](WebServerOptions& options) { api.install(options); });
  api.disk.open();
  RawConnection client(port());
  ASSERT_TRUE(client.send_all("POST /api/answer HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n"
                              "Expect: 100-continue\r\nContent-Length: 7\r\n\r\n"));
  ASSERT_TRUE(client.read_until("HTTP/1.1 100 Continue\r\n\r\n")) << client.received();
  ASSERT_TRUE(client.send_all("trial=1"));
  ASSERT_TRUE(client.read_to_end());
  const std::string after = client.received().substr(client.received().find("\r\n\r\n") + 4);
  EXPECT_EQ(parse_response(after).status, 200) << client.received();
  EXPECT_EQ(api.answers_synced, 1);
}

// Requests pipelined in one write get their replies in order on the one connection. Seen to
// fail (only the first reply came) with the buffer cleared after each request in Session::send.
TEST_F(RequestFraming, PipelinedRequestsAreAnsweredInOrder) {
  start_server();
  RawConnection client(port());
  ASSERT_TRUE(client.send_all("GET /index.html HTTP/1.1\r\nHost: localhost\r\n\r\n"
                              "GET /images/index.json HTTP/1.1\r\nHost: localhost\r\n\r\n"
                              "GET /vimg.js HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"));
  ASSERT_TRUE(client.read_to_end());
  const std::string& all = client.received();
  const std::size_t page = all.find("<title>site</title>"), list = all.find("[\"smiley\"]"), script = all.find("export const x");
  ASSERT_NE(page, std::string::npos) << all;
  ASSERT_NE(list, std::string::npos) << all;
  ASSERT_NE(script, std::string::npos) << all;
  EXPECT_LT(page, list);
  EXPECT_LT(list, script);
  EXPECT_EQ(client.count_of("HTTP/1.1 200 OK\r\n"), 3);
}

// Framings a proxy in front could read otherwise than the server (request smuggling): 400, the
// route never runs. Seen to fail with unambiguous_framing returning true.
TEST_F(RequestFraming, AmbiguousFramingIs400) {
  StubApi api(root_ / "answers.txt");
  start_server([&](WebServerOptions& options) { api.install(options); });
  api.disk.open();
  const std::string head = "POST /api/answer HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n";
  EXPECT_EQ(send_raw(port(), head + "Content-Length: 7\r\nTransfer-Encoding: chunked\r\n\r\n" + chunked("trial=1", 7)).status, 400);
  EXPECT_EQ(send_raw(port(), head + "Transfer-Encoding: chunked\r\nContent-Length: 7\r\n\r\n" + chunked("trial=1", 7)).status, 400);
  EXPECT_EQ(send_raw(port(), head + "Content-Length: 7\r\nContent-Length: 7\r\n\r\ntrial=1").status, 400);
  EXPECT_EQ(send_raw(port(), head + "Content-Length: 7, 7\r\n\r\ntrial=1").status, 400);
  EXPECT_EQ(send_raw(port(), head + "Content-Length: 7\r\nContent-Length: 9\r\n\r\ntrial=1").status, 400);
  EXPECT_EQ(send_raw(port(), head + "Transfer-Encoding: gzip\r\n\r\n").status, 400);
  EXPECT_EQ(api.answers_synced, 0);
  EXPECT_EQ(send_raw(port(), head + "Content-Length: 7\r\n\r\ntrial=1").status, 200);
}

}  // namespace
}  // namespace vimg::test
