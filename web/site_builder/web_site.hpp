#pragma once
// The site `vimg web` writes and `vimg serve` serves (docs/web-site.md): the page and the WebAssembly
// renderer built by the `web` preset, and each image compiled to a .vsc (storage/vsc/vsc_image.hpp) by
// the native reader. Nothing in the site is fetched from elsewhere at run time.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "primitives/actuator/response_params.hpp"
#include "storage/diagnostic.hpp"

namespace vimg {

struct WebSiteOptions {
  ResponseParams actuator;  // the response the page renders for; the ideal actuator by default
};

// The options for `--actuator P` (a profile file or a shipped profile's name; empty: the ideal
// actuator). The profile is read and parsed here, once per command: `vimg serve` compiles every
// save with the same options. Nothing, with the reader's messages (FILE:LINE: error: ...) in
// `errors`, when the profile cannot be used.
std::optional<WebSiteOptions> web_site_options(const std::string& actuator_profile, std::vector<std::string>& errors);

// The page's files, in the folder the web build wrote them to: VIMG_WEB_ASSETS if set, else the
// folder CMake named (VIMG_WEB_ASSETS_DIR).
std::filesystem::path web_assets_dir();
inline constexpr const char* kWebAssetFiles[] = {"index.html", "picture.js", "audio_clock.js", "vimg.js", "vimg.wasm",
                                                   "worklet.js"};
// The study's pages (vimg serve --study, docs/matching-test.md "The matching test in the browser"), beside those:
// study.html loads study.js and the study_*.js it uses.
inline constexpr const char* kStudyAssetFiles[] = {"study.html", "study.js", "study_answers.js", "study_audio.js",
                                                   "study_screens.js", "study_touch.js", "dashboard.html"};

// The name an image has in the site (images/NAME.vsc): its file stem, characters other than
// [A-Za-z0-9_.-] replaced by '_'.
std::string web_image_name(const std::filesystem::path& image);

// Writes the page's files (kWebAssetFiles), DIR/images/NAME.vsc per image and
// DIR/images/index.json (the names in order). Returns the diagnostics (FILE:LINE: error: ...); the
// site is complete only when there is no error. Files are written atomically.
std::vector<Diagnostic> build_web_site(const std::vector<std::filesystem::path>& images, const WebSiteOptions& options,
                                       const std::filesystem::path& out_dir);

// Adds the study's pages (kStudyAssetFiles) to a site build_web_site wrote.
std::vector<Diagnostic> add_study_pages(const std::filesystem::path& out_dir);

// Rewrites only DIR/images/NAME.vsc of one image (a save seen by `vimg serve`).
std::vector<Diagnostic> update_web_image(const std::filesystem::path& image, const WebSiteOptions& options,
                                         const std::filesystem::path& out_dir);

}  // namespace vimg
