// `vimg serve IMAGE...|DIR [--port N] [--lan] [--tls CERT KEY] [--actuator P]` (docs/web-serving.md,
// "Serving"): builds the site of the images into a private temporary folder (or takes DIR, a site `vimg web` wrote),
// serves it read-only (web/server/web_server.hpp) and prints its URL; each save of an image is
// compiled again and pushed to the open pages. SIGINT/SIGTERM stop it: the temporary site is
// removed and it exits 130/143. With --study it serves a matching test instead (cmd_serve_study.cpp).
#include <pthread.h>
#include <signal.h>

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "cli/command.hpp"
#include "cli/serve_study.hpp"
#include "web/server/lan_address.hpp"
#include "web/server/served_images.hpp"
#include "web/server/terminal_qr.hpp"
#include "web/site_builder/web_site.hpp"

namespace vimg::cli {

namespace {

namespace fs = std::filesystem;

constexpr int kDefaultPort = 8765;

struct ServeArgs {
  std::vector<std::string> inputs;
  int port = kDefaultPort;
  bool lan = false;
  std::string actuator;
  std::vector<std::string> tls;
  std::string study, results;
};

// "http://HOST:PORT/", https with --tls.
std::string url_of(const ServeArgs& a, const std::string& host, int port) {
  std::string url = web::site_url(host, port);
  if (!a.tls.empty()) url.insert(4, "s");
  return url;
}

void print_addresses(const ServeArgs& a, int port) {
  if (!a.lan) {
    std::printf("vimg serve: %s (Ctrl-C stops)\n", url_of(a, "127.0.0.1", port).c_str());
    return;
  }
  const auto lan = web::first_lan_ipv4_address();
  if (!lan) {
    std::printf("vimg serve: %s on every interface; no LAN address found (Ctrl-C stops)\n",
                url_of(a, "127.0.0.1", port).c_str());
    return;
  }
  const std::string url = url_of(a, *lan, port);
  std::printf("vimg serve: %s on the LAN (Ctrl-C stops)\n", url.c_str());
  if (const auto qr = web::terminal_qr_code(url)) std::printf("%s", qr->c_str());
}

int run_serve(const ServeArgs& a) {
  const char* program = "vimg serve";
  std::error_code ec;
  if (a.study.empty() != a.results.empty()) return usage_error(program, "--study and --results go together");
  if (!a.study.empty() && !a.inputs.empty()) return usage_error(program, "--study serves the study's images: give no INPUT");
  if (!a.study.empty() && !a.actuator.empty()) return usage_error(program, "--actuator does not apply to --study");
  if (a.study.empty() && a.inputs.empty()) return usage_error(program, "give images, a built site, or --study");
  const bool serve_folder = a.inputs.size() == 1 && fs::is_directory(a.inputs.front(), ec);
  for (const std::string& input : a.inputs) {
    if (!serve_folder && fs::is_directory(input, ec)) {
      return usage_error(program, input + " is a folder: give either images or one folder of a built site");
    }
  }
  if (serve_folder && !a.actuator.empty()) {
    return usage_error(program, "--actuator applies to images, not to a built site (" + a.inputs.front() + ")");
  }
  // From here SIGINT/SIGTERM wait for wait_for_stop_signal (the server's threads inherit the mask),
  // so that the site is always removed and the watcher never stops in the middle of a rewrite.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  if (!a.study.empty()) return run_serve_study({a.study, a.results, a.port, a.lan, a.tls}, stop_signals);

  web::WebServerOptions server_options;
  server_options.host = a.lan ? "0.0.0.0" : "127.0.0.1";
  server_options.port = a.port;
  if (!a.tls.empty()) {
    server_options.tls_cert_pem = a.tls[0];
    server_options.tls_key_pem = a.tls[1];
  }
  std::unique_ptr<web::WebServer> built_site;  // DIR
  std::unique_ptr<web::ServedImages> images;   // IMAGE...
  if (serve_folder) {
    server_options.site_dir = a.inputs.front();
    if (!fs::is_regular_file(server_options.site_dir / "index.html", ec)) {
      std::fprintf(stderr, "%s: error: not a built site (no index.html); write one with vimg web IMAGE... --out %s\n",
                   a.inputs.front().c_str(), a.inputs.front().c_str());
      return kExitFailure;
    }
    built_site = std::make_unique<web::WebServer>(server_options);
    if (const auto problem = built_site->start()) {
      std::fprintf(stderr, "%s: %s\n", program, problem->c_str());
      return kExitFailure;
    }
  } else {
    std::vector<std::string> profile_errors;  // the profile is read once, for every save
    const std::optional<WebSiteOptions> site_options = web_site_options(a.actuator, profile_errors);
    for (const std::string& e : profile_errors) std::fprintf(stderr, "%s\n", e.c_str());
    if (!site_options) return kExitFailure;
    images = std::make_unique<web::ServedImages>(std::vector<fs::path>(a.inputs.begin(), a.inputs.end()),
                                                 *site_options, server_options,
                                                 [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
    if (!images->start()) return kExitFailure;
  }
  web::WebServer& server = built_site ? *built_site : images->server();
  print_addresses(a, server.port());
  std::fflush(stdout);
  const int signal_number = wait_for_stop_signal(stop_signals, server);
  if (images) {
    images->stop();  // the watcher first: a rewrite under way ends
  } else {
    built_site->stop();
  }
  if (signal_number == 0) {
    std::fprintf(stderr, "%s: the server stopped\n", program);
    return kExitFailure;
  }
  return signal_number == SIGTERM ? cmdline::kExitSigterm : cmdline::kExitSigint;
}

}  // namespace

// The signals are blocked in every thread, so they wait here rather than end the process.
int wait_for_stop_signal(const sigset_t& stop_signals, const web::WebServer& server) {
  const timespec check_every{1, 0};  // only to notice a server that stopped by itself
  while (server.running()) {
    const int signal_number = sigtimedwait(&stop_signals, nullptr, &check_every);
    if (signal_number > 0) return signal_number;
  }
  return 0;
}

void add_serve_command(CLI::App& vimg, int& exit_code) {
  CLI::App* sub = vimg.add_subcommand("serve", "serve images (or a built site) to a browser and push each save to it");
  auto a = std::make_shared<ServeArgs>();
  sub->add_option("INPUT", a->inputs, "images (.vimg, .xml, .png), or one folder written by vimg web");
  sub->add_option("--port", a->port, "TCP port (default " + std::to_string(kDefaultPort) + "; 0: any free port, printed)")
      ->check(CLI::Range(0, 65535));
  sub->add_flag("--lan", a->lan, "listen on every interface and print the LAN URL with a QR code (default: 127.0.0.1 only)");
  sub->add_option("--tls", a->tls, "CERT.pem KEY.pem: serve HTTPS (a secure context on a LAN: tablets get the AudioWorklet)")
      ->expected(2);
  sub->add_option("--study", a->study, "a matching study file: serve the study to participants' browsers (docs/studies.md)");
  sub->add_option("--results", a->results, "with --study: the folder of the trial files (and of the study's secret)");
  sub->add_option("--actuator", a->actuator, "actuator profile (assets/profiles/*.xml) the page renders for (default: ideal)");
  sub->footer("Read-only: GET and HEAD of the site's files only (with --study, one POST: a participant's answer), no listing, nothing outside the site. Images are "
              "watched: each save is compiled again and pushed to the open pages (Server-Sent Events at /events). "
              "One log line per request on stderr. SIGINT/SIGTERM remove the temporary site and exit 130/143. "
              "With --study: the study page, answers appended to DIR/ID.trials.csv, the dashboard URL printed; "
              "participants' links: vimg study link DIR --participant ID. "
              "See docs/web.md.");
  sub->callback([a, &exit_code] { exit_code = run_serve(*a); });
}

}  // namespace vimg::cli
