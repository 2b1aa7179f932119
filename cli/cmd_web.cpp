// `vimg web IMAGE... --out DIR [--actuator P]` (docs/web-site.md): writes a self-contained site that
// plays the images in a browser (the page, the WebAssembly renderer, each image as a .vsc).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "web/site_builder/web_site.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::cli {

namespace {

struct WebArgs {
  std::vector<std::string> images;
  std::string out;
  std::string actuator;  // profile; empty: the ideal actuator
};

int run_web(const WebArgs& a) {
  const std::vector<std::filesystem::path> images(a.images.begin(), a.images.end());
  std::vector<std::string> profile_errors;
  const std::optional<WebSiteOptions> options = web_site_options(a.actuator, profile_errors);
  for (const std::string& e : profile_errors) std::fprintf(stderr, "%s\n", e.c_str());
  if (!options) return kExitFailure;
  const std::vector<Diagnostic> diagnostics = build_web_site(images, *options, a.out);
  print_diagnostics(diagnostics);
  if (has_errors(diagnostics)) return kExitFailure;
  std::printf("%s: a site of %zu image%s; a browser loads it from a server: vimg serve %s\n", a.out.c_str(),
              images.size(), images.size() == 1 ? "" : "s", a.out.c_str());
  return kExitOk;
}

}  // namespace

void add_web_command(CLI::App& vimg, int& exit_code) {
  CLI::App* sub = vimg.add_subcommand("web", "write a self-contained web site that plays the images in a browser");
  auto a = std::make_shared<WebArgs>();
  sub->add_option("IMAGE", a->images, "images to put in the site (.vimg, .xml or .png)")->required();
  sub->add_option("--out", a->out, "the site's folder (index.html, picture.js, vimg.js, vimg.wasm, worklet.js, images/)")->required();
  sub->add_option("--actuator", a->actuator, "actuator profile (assets/profiles/*.xml) the page renders for (default: ideal)");
  sub->footer("Nothing in the site is fetched from elsewhere at run time. Browsers do not run WebAssembly from "
              "file:// pages: serve the folder (vimg serve DIR, or any static server). See docs/web.md.");
  sub->callback([a, &exit_code] { exit_code = run_web(*a); });
}

}  // namespace vimg::cli
