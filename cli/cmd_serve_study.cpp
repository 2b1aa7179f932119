// `vimg serve --study STUDY.xml --results DIR [--port N] [--lan] [--tls CERT KEY]`
// (docs/matching-test.md, "The matching test in the browser"): the study's images built into a
// private temporary site with the study's pages, served with the study API
// (web/study_server/study_service.hpp). It prints the researcher's dashboard URL; `vimg study
// link DIR --participant ID` prints participants' links.
#include <cstdio>
#include <set>
#include <variant>

#include "cli/command.hpp"
#include "cli/serve_study.hpp"
#include "storage/print_diagnostics.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/served_url_file.hpp"
#include "web/server/lan_address.hpp"
#include "web/server/served_images.hpp"
#include "web/site_builder/web_site.hpp"
#include "web/study_server/study_keys.hpp"
#include "web/study_server/study_service.hpp"

namespace vimg::cli {

namespace {

namespace fs = std::filesystem;

constexpr const char* kProgram = "vimg serve";

// The address pages reach the server at: the LAN's with --lan (127.0.0.1 when there is none),
// https with --tls.
std::string base_url(const StudyServeArgs& a, int port) {
  std::string host = "127.0.0.1";
  if (a.lan) {
    if (const auto lan = web::first_lan_ipv4_address()) host = *lan;
  }
  std::string url = web::site_url(host, port);
  if (!a.tls.empty()) url.insert(4, "s");
  return url;
}

}  // namespace

std::string participant_link(const std::string& base_url, const std::string& participant, const std::string& key) {
  return base_url + "study.html#participant=" + participant + "&key=" + key;
}

int run_serve_study(const StudyServeArgs& a, const sigset_t& stop_signals) {
  const StudyFileResult<MatchingStudy> loaded = load_matching_study(a.study);
  print_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) return kExitFailure;
  std::error_code ec;
  if (!fs::is_directory(a.results, ec)) {
    std::fprintf(stderr, "%s: error: the results folder does not exist (make it first)\n", a.results.c_str());
    return kExitFailure;
  }
  auto keys = web::StudyKeys::open(a.results);
  if (const auto* error = std::get_if<std::string>(&keys)) {
    std::fprintf(stderr, "%s\n", error->c_str());
    return kExitFailure;
  }
  // The site: every image once (an image may be in several sets), and the study's pages.
  web::TemporaryFolder site("vimg-study-");
  if (site.path().empty()) {
    std::fprintf(stderr, "%s: error: cannot make a temporary folder for the site\n", kProgram);
    return kExitFailure;
  }
  std::vector<fs::path> images;
  std::set<fs::path> seen;
  std::vector<std::vector<std::string>> names;
  for (const StudyImageSet& set : loaded.study->sets) {
    auto& set_names = names.emplace_back();
    for (const fs::path& image : set.images) {
      if (seen.insert(image).second) images.push_back(image);
      set_names.push_back(web_image_name(image));
    }
  }
  std::vector<Diagnostic> built = build_web_site(images, WebSiteOptions{}, site.path());
  if (!has_errors(built)) {
    std::vector<Diagnostic> pages = add_study_pages(site.path());
    built.insert(built.end(), pages.begin(), pages.end());
  }
  print_diagnostics(built);
  if (has_errors(built)) return kExitFailure;

  web::StudyService service(*loaded.study, names, a.results, std::get<web::StudyKeys>(keys));
  web::WebServerOptions options;
  options.site_dir = site.path();
  options.host = a.lan ? "0.0.0.0" : "127.0.0.1";
  options.port = a.port;
  service.install(options);  // its cheap refusals on the network thread, the rest on the workers
  if (!a.tls.empty()) {
    options.tls_cert_pem = a.tls[0];
    options.tls_key_pem = a.tls[1];
  }
  web::WebServer server(options);
  if (const auto problem = server.start()) {
    std::fprintf(stderr, "%s: %s\n", kProgram, problem->c_str());
    return kExitFailure;
  }
  const std::string base = base_url(a, server.port());
  if (const auto error = record_served_url(a.results, base)) {
    std::fprintf(stderr, "%s: warning: %s (vimg study link then needs --url)\n", kProgram, error->c_str());
  }
  const std::string researcher_key = std::get<web::StudyKeys>(keys).researcher_key();
  std::printf("vimg serve: study %s, results in %s\n", a.study.c_str(), a.results.c_str());
  std::printf("vimg serve: dashboard %sdashboard.html#key=%s (Ctrl-C stops)\n", base.c_str(), researcher_key.c_str());
  std::printf("vimg serve: a participant's link: vimg study link %s --participant ID\n", a.results.c_str());
  std::fflush(stdout);
  const int signal_number = wait_for_stop_signal(stop_signals, server);
  server.stop();
  if (signal_number == 0) {
    std::fprintf(stderr, "%s: the server stopped\n", kProgram);
    return kExitFailure;
  }
  return signal_number == SIGTERM ? cmdline::kExitSigterm : cmdline::kExitSigint;
}

}  // namespace vimg::cli
