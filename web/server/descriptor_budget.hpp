#pragma once
// One budget of file descriptors for the server's sockets and the files the routes hold
// (docs/web-serving.md, "Connections"): the process may open `descriptor_limit` (its soft limit, raised to
// the hard one at start). Of these, kKeptDescriptors stay free for files opened while serving (a
// file read for a reply, a participant's first trial file, the watcher, the log); the long-held
// files (each participant's trial file stays open) come off the connections' share as they open.
// So with every connection place taken, a new participant's first answer still opens its file.
// A connection beyond the cap is refused (answered 503: web/server/busy_refusal.hpp) while fewer
// than kMaxRefusingConnections are being refused, and closed at once beyond that.
#include "web/server/http_message.hpp"

namespace vimg::web {

inline constexpr int kKeptDescriptors = 64;

// Raises the soft limit of open descriptors to the hard one; the limit then (INT_MAX if none).
int raise_descriptor_limit();

struct DescriptorUse {
  int connections = 0;  // served connections open
  int refusing = 0;     // connections being answered 503
  int files_held = 0;   // files the routes keep open (trial files)
};

enum class Admission { serve, refuse_busy, close };

// What to do with one more accepted connection.
Admission admit_connection(const DescriptorUse& use, int max_connections, int descriptor_limit);

// The connections served at once when no file is held: the cap, lowered to what the descriptors allow.
int connection_cap(int max_connections, int descriptor_limit);

}  // namespace vimg::web
