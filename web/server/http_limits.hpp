#pragma once
// The bounds every connection of the server is held to (docs/web-serving.md, "Connections"), and what the
// engine counts (web/server/http_engine.hpp), without the network library's types.
#include <chrono>
#include <cstddef>

namespace vimg::web {

// Bounds of one connection. A participant's page sends its request at once (a few hundred bytes);
// a client that trickles its header, says nothing, or sends more hits these long before.
inline constexpr std::chrono::seconds kHeaderDeadline{5};   // connect or keep-alive start to end of the header
inline constexpr std::chrono::seconds kBodyDeadline{5};     // end of the header to end of the body
inline constexpr std::chrono::seconds kTlsHandshakeDeadline{5};
inline constexpr std::chrono::seconds kWriteDeadline{10};   // a reply's write, plus 1 s per kWriteBytesPerSecond
inline constexpr std::size_t kWriteBytesPerSecond = 256 * 1024;
inline constexpr std::chrono::seconds kClosingDeadline{1};  // reading what is left before closing
inline constexpr std::size_t kMaxRequestLineBytes = 8192;   // beyond: 414
inline constexpr std::size_t kMaxHeaderLineBytes = 8192;    // beyond: 400
inline constexpr std::size_t kMaxHeaderBytes = 16384;       // the whole header; beyond: 414 or 400
// Connections open at once (participants, pages, and anything else); one more is answered 503
// (its request head read first) and closed. Lowered to what the process's descriptors allow
// (web/server/descriptor_budget.hpp).
inline constexpr int kMaxConnections = 4000;
// Connections beyond the cap being answered 503 at once; beyond these, one more is closed unanswered.
inline constexpr int kMaxRefusingConnections = 64;
// The threads that run the routes that only read (files, the study's state, progress and report),
// and, apart, those that run the writing ones (POST: a participant's answer, fsync'd), so that a
// slow disk stalls the answers only. The network is one thread of its own.
inline constexpr int kRouteWorkerThreads = 4;
inline constexpr int kWriteWorkerThreads = 2;
// The bytes of file copies the replies in flight hold at once (web/server/file_copies.hpp): one
// copy per file, shared by every reply of it. A request whose copy would pass it waits, holding no
// reply, until a copy is freed (or one it may share made), for kReplyBudgetWait at most; then 503.
inline constexpr std::size_t kReplyBudgetBytes = std::size_t{128} << 20;
inline constexpr std::chrono::seconds kReplyBudgetWait{10};
// How long an event stream stays open; the page's EventSource then opens another (after the
// stream's retry hint) and resumes at its Last-Event-ID.
inline constexpr std::chrono::seconds kEventStreamLifetime{600};
// The retry hint of a stream that could not be opened (every place taken): the page tries again then.
inline constexpr std::chrono::milliseconds kEventStreamFullRetry{10000};
// On SIGINT/SIGTERM: how long the routes under way (an answer being synced) and their replies may
// take before every connection is closed.
inline constexpr std::chrono::seconds kStopGraceDeadline{10};

// The bounds above, as one server holds them; tests shrink some to see them act in milliseconds
// (the defaults are the documented values).
struct HttpLimits {
  std::chrono::milliseconds header_deadline = kHeaderDeadline;
  std::chrono::milliseconds body_deadline = kBodyDeadline;
  std::chrono::milliseconds tls_handshake_deadline = kTlsHandshakeDeadline;
  std::chrono::milliseconds write_deadline = kWriteDeadline;
  std::size_t write_bytes_per_second = kWriteBytesPerSecond;
  std::chrono::milliseconds closing_deadline = kClosingDeadline;
  int max_connections = kMaxConnections;
  std::size_t reply_budget_bytes = kReplyBudgetBytes;
  std::chrono::milliseconds reply_budget_wait = kReplyBudgetWait;  // 0: 503 at once
  std::chrono::milliseconds event_stream_lifetime = kEventStreamLifetime;
  std::chrono::milliseconds stop_grace_deadline = kStopGraceDeadline;
};

// What the engine has done so far, for tests and the benchmarks (read from any thread).
struct HttpEngineCounts {
  int open_connections = 0;    // served connections open now
  long refused_busy = 0;       // connections beyond the cap answered 503 (or being answered)
  long closed_unanswered = 0;  // connections beyond even the refusals' places, closed at once
  long routes_queued = 0;      // requests handed to a worker's queue
  long routes_dropped = 0;     // routes not run because their client had gone
  long routes_failed = 0;      // routes that threw (answered 500)
  long refused_early = 0;      // requests refused before they waited for anything (HttpRoutes::screen)
  int waiting_for_room = 0;    // requests waiting now for room in the reply budget (holding no reply)
  long room_waits_expired = 0; // requests that waited kReplyBudgetWait in vain (answered 503)
};

}  // namespace vimg::web
