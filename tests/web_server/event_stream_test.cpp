// /events (docs/web-serving.md, "Serving"): an open page gets "event: image" with the image's name for each
// publish after it connected, and a save of a watched image (by rename, as editors and vimg save)
// rewrites the site's copy first and then reaches the page. Waits are on the stream's bytes; the
// socket's receive bound only ends a hang.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <thread>

#include "storage/atomic_file.hpp"
#include "tests/net/raw_http.hpp"
#include "tests/web_server/site_fixture.hpp"
#include "web/server/event_stream.hpp"
#include "web/server/live_site.hpp"

namespace vimg::test {
namespace {

using EventStream = SiteFixture;

// Opens /events and waits for the server's greeting: from then on, every publish reaches it.
void open_events(RawConnection& connection) {
  ASSERT_TRUE(connection.connected());
  connection.send_all("GET /events HTTP/1.1\r\nHost: localhost\r\n\r\n");
  ASSERT_TRUE(connection.read_until(": connected\n")) << connection.received();
  HttpResponse head = parse_response(connection.received());
  EXPECT_EQ(head.status, 200);
  EXPECT_EQ(head.headers["content-type"], "text/event-stream");
  EXPECT_EQ(head.headers["cache-control"], "no-store");
}

TEST(EventMessage, EachLineOfTheDataIsADataField) {
  EXPECT_EQ(web::format_event_message("image", "smiley"), "event: image\ndata: smiley\n\n");
  EXPECT_EQ(web::format_event_message("image", "a\nb\r\nc\rd"), "event: image\ndata: a\ndata: b\ndata: c\ndata: d\n\n");
}

TEST_F(EventStream, EveryOpenPageGetsEachImageEvent) {
  web::WebServer& server = start_server();
  RawConnection first(port()), second(port());
  open_events(first);
  open_events(second);
  server.publish_image_changed("smiley");
  server.publish_image_changed("grid");
  for (RawConnection* page : {&first, &second}) {
    ASSERT_TRUE(page->read_until("data: grid\n\n")) << page->received();
    const std::string& text = page->received();
    EXPECT_LT(text.find("event: image\ndata: smiley\n\n"), text.find("event: image\ndata: grid\n\n"));
  }
  EXPECT_EQ(server.open_event_streams(), 2);
}

TEST_F(EventStream, StopEndsTheOpenStreams) {
  web::WebServer& server = start_server();
  RawConnection page(port());
  open_events(page);
  server.stop();
  // The server closes the stream (an orderly end, not the hang bound), after the greeting only.
  ASSERT_TRUE(page.read_to_end()) << "the stream was not closed: " << page.received();
  EXPECT_EQ(page.received().find("event: "), std::string::npos) << page.received();
  EXPECT_EQ(server.open_event_streams(), 0);
}

// The check above rests on read_to_end telling an orderly end of the stream from a wait that
// only stopped at its bound: against a peer that keeps the connection open it is false, against
// one that closes it is true.
TEST(RawConnectionTest, ReadToEndIsTrueOnlyWhenThePeerCloses) {
  const int listener = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  ASSERT_GE(listener, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  ASSERT_EQ(::bind(listener, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(::listen(listener, 2), 0);
  ASSERT_EQ(::getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length), 0);
  const int port = ntohs(address.sin_port);
  RawConnection open_one(port);
  const int kept = ::accept(listener, nullptr, nullptr);
  ASSERT_GE(kept, 0);
  ASSERT_EQ(::send(kept, "x", 1, MSG_NOSIGNAL), 1);
  EXPECT_FALSE(open_one.read_to_end(std::chrono::milliseconds(200))) << "the peer never closed";
  EXPECT_EQ(open_one.received(), "x");
  RawConnection closed_one(port);
  const int closing = ::accept(listener, nullptr, nullptr);
  ASSERT_GE(closing, 0);
  ASSERT_EQ(::send(closing, "y", 1, MSG_NOSIGNAL), 1);
  ::close(closing);
  EXPECT_TRUE(closed_one.read_to_end());
  EXPECT_EQ(closed_one.received(), "y");
  ::close(kept);
  ::close(listener);
}

TEST_F(EventStream, AtMostKMaxEventStreamsAreOpen) {
  start_server();
  std::vector<std::unique_ptr<RawConnection>> pages;
  for (int i = 0; i < web::kMaxEventStreams; ++i) {
    pages.push_back(std::make_unique<RawConnection>(port()));
    open_events(*pages.back());
  }
  // One more page is not refused for good (a 503 would end its EventSource): it gets a stream
  // that ends at once with the retry hint, and its EventSource tries again then. Seen to fail
  // with the 503 put back in WebServer's serve_events.
  const HttpResponse full = exchange(port(), "GET", "/events");
  EXPECT_EQ(full.status, 200);
  EXPECT_EQ(full.headers.at("content-type"), "text/event-stream");
  EXPECT_NE(full.body.find("retry: " + std::to_string(web::kEventStreamFullRetry.count()) + "\n\n"), std::string::npos)
      << full.body;
  EXPECT_EQ(exchange(port(), "GET", "/index.html").status, 200);  // files are still served
}

TEST_F(EventStream, ASavedImageIsRewrittenThenPushed) {
  const fs::path image = root_ / "smiley.vimg";
  write_text(image, "first");
  const fs::path copy = site_ / "images" / "smiley.vsc";
  web::WebServerOptions options;
  options.site_dir = site_;
  options.log_line = [](const std::string&) {};
  // The refresh stands in for update_web_image: the site's copy becomes the image's bytes.
  web::LiveSite live(options, {image}, [&](const fs::path& saved) -> std::optional<std::string> {
    std::ifstream in(saved, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (write_file_atomically(copy, bytes)) return std::nullopt;
    return saved.stem().string();
  });
  ASSERT_FALSE(live.start());
  RawConnection page(live.server().port());
  open_events(page);
  write_text(root_ / "unrelated.vimg", "not watched");  // a save of another file says nothing
  ASSERT_FALSE(write_file_atomically(image, "second"));  // temporary + rename, as a save
  ASSERT_TRUE(page.read_until("event: image\ndata: smiley\n\n")) << page.received();
  EXPECT_EQ(page.received().find("unrelated"), std::string::npos);
  std::ifstream in(copy, std::ios::binary);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()), "second");
  // A write in place (an editor that truncates and writes) is a save too.
  write_text(image, "third");
  ASSERT_TRUE(page.read_until_count("event: image\ndata: smiley\n\n", 2)) << page.received();
}

// A stream ends after its lifetime (shrunk here to 300 ms; the default is kEventStreamLifetime)
// with the chunked body's last chunk, and its place is free again; each message carries its id,
// and a page that reopens with Last-Event-ID gets what it missed. Seen to fail (the stream stayed
// open until the test's bound) with EventStreamWriter::arm's lifetime made 1000 times longer, and (the
// missed message never came) with open_stream ignoring last_event_id.
TEST_F(EventStream, AStreamEndsAfterItsLifetimeAndResumesAtItsLastEventId) {
  web::WebServer& server = start_server([](WebServerOptions& options) {
    options.limits.event_stream_lifetime = std::chrono::milliseconds(300);
  });
  RawConnection page(port());
  open_events(page);
  server.publish_image_changed("first");
  ASSERT_TRUE(page.read_until("id: 1\nevent: image\ndata: first\n\n")) << page.received();
  ASSERT_TRUE(page.read_to_end()) << "the stream outlived its lifetime: " << page.received();
  EXPECT_NE(page.received().find("\r\n0\r\n\r\n"), std::string::npos) << "no last chunk";
  const auto give_up = std::chrono::steady_clock::now() + kHangBound;
  while (server.open_event_streams() > 0 && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
  EXPECT_EQ(server.open_event_streams(), 0);
  server.publish_image_changed("missed");  // while the page had no stream
  RawConnection again(port());
  ASSERT_TRUE(again.send_all("GET /events HTTP/1.1\r\nHost: localhost\r\nLast-Event-ID: 1\r\n\r\n"));
  ASSERT_TRUE(again.read_until("id: 2\nevent: image\ndata: missed\n\n")) << again.received();
  EXPECT_EQ(again.received().find("data: first"), std::string::npos);
}

// A study publishes nothing: with an API, /events is not served. Seen to fail (200, a stream)
// with the `!options.api` condition removed from WebServer's respond.
TEST_F(EventStream, NotServedWithAnApi) {
  start_server([](WebServerOptions& options) {
    options.api = [](const web::ApiRequest&) { return web::ApiReply{}; };
  });
  EXPECT_EQ(exchange(port(), "GET", "/events").status, 404);
}

}  // namespace
}  // namespace vimg::test
