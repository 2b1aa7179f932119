#pragma once
// `vimg serve --study STUDY.xml --results DIR` (cmd_serve_study.cpp) and what it shares with
// `vimg serve` (cmd_serve.cpp) and `vimg study link` (cmd_study.cpp).
#include <signal.h>

#include <filesystem>
#include <string>
#include <vector>

#include "web/server/web_server.hpp"

namespace vimg::cli {

struct StudyServeArgs {
  std::string study;
  std::string results;
  int port = 0;
  bool lan = false;
  std::vector<std::string> tls;  // CERT.pem KEY.pem, or empty
};

// A participant's link: BASE + "study.html#participant=ID&key=KEY" (the key after '#' never
// reaches a server or its logs). BASE ends in '/'.
std::string participant_link(const std::string& base_url, const std::string& participant, const std::string& key);

// Blocks until SIGINT or SIGTERM arrives (returns it) or the server has stopped by itself (0).
int wait_for_stop_signal(const sigset_t& stop_signals, const web::WebServer& server);

// Runs the study server until a signal; the exit status. The stop signals are blocked already.
int run_serve_study(const StudyServeArgs& a, const sigset_t& stop_signals);

}  // namespace vimg::cli
