#include "web/site_builder/web_site.hpp"

#include "storage/shipped_data.hpp"

#include <cstdlib>
#include <optional>
#include <set>
#include <system_error>

#include "storage/actuator_profile.hpp"
#include "storage/atomic_file.hpp"
#include "storage/diagnostic.hpp"
#include "storage/image_io.hpp"
#include "storage/read_file.hpp"
#include "storage/vsc/vsc_image.hpp"

namespace vimg {

namespace {

// The biggest asset is the wasm (a few hundred KiB); this only guards against a wrong folder.
constexpr std::size_t kMaxAssetBytes = std::size_t{64} << 20;

Diagnostic error_of(const std::string& file, std::string message) {
  Diagnostic d;
  d.file = file;
  d.message = std::move(message);
  return d;
}

bool make_dir(const std::filesystem::path& dir, std::vector<Diagnostic>& out) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) out.push_back(error_of(dir.string(), "cannot create the folder: " + ec.message()));
  return !ec;
}

bool write_or_report(const std::filesystem::path& path, std::string_view bytes, std::vector<Diagnostic>& out) {
  if (auto problem = write_file_atomically(path, bytes)) {
    out.push_back(error_of(path.string(), *problem));
    return false;
  }
  return true;
}

// The page's files named by `names`, read from web_assets_dir(); false (reported) when one is missing.
template <class Names>
bool read_assets(const Names& names, std::vector<std::pair<std::string, std::string>>& files, std::vector<Diagnostic>& out) {
  const std::filesystem::path assets = web_assets_dir();
  for (const char* name : names) {
    FileReadResult read = read_regular_file(assets / name, kMaxAssetBytes);
    if (!read.bytes) {
      out.push_back(error_of((assets / name).string(),
                             read.error + "; build the page with `cmake --preset web && cmake --build --preset web` "
                                          "(or set VIMG_WEB_ASSETS to the folder holding " + name + ")"));
      return false;
    }
    files.emplace_back(name, std::move(*read.bytes));
  }
  return true;
}

// Compiles one image into DIR/images/NAME.vsc; false after adding the diagnostics.
bool write_image(const std::filesystem::path& image, const ResponseParams& response, const std::filesystem::path& out_dir,
                 std::vector<Diagnostic>& out) {
  LoadResult loaded = load_image_file(image);
  const bool ok = loaded.ok();
  append_diagnostics(out, std::move(loaded.diagnostics));
  if (!ok) return false;
  const std::string bytes = write_vsc({*loaded.image, response});
  // What the page will read must read: a name or an id beyond the .vsc limits is said here.
  const VscReadResult check = read_vsc(bytes, image.string());
  if (!check.image) {
    out.push_back(error_of(image.string(), "cannot be compiled for the web: " + check.error));
    return false;
  }
  if (!make_dir(out_dir / "images", out)) return false;
  return write_or_report(out_dir / "images" / (web_image_name(image) + ".vsc"), bytes, out);
}

std::string json_string(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

}  // namespace

std::filesystem::path web_assets_dir() {
  if (const char* env = std::getenv("VIMG_WEB_ASSETS"); env != nullptr && *env != '\0') return env;
  // Installed: PREFIX/share/vibroimage/web; in the build tree a link to the web build's output.
  if (const auto data = shipped_data_dir()) return *data / "web";
  return "web";
}

std::string web_image_name(const std::filesystem::path& image) {
  std::string name = image.stem().string();
  for (char& c : name) {
    const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '-';
    if (!plain) c = '_';
  }
  if (name.empty() || name.front() == '.') name.insert(name.begin(), '_');
  return name;
}

std::vector<Diagnostic> build_web_site(const std::vector<std::filesystem::path>& images, const WebSiteOptions& options,
                                       const std::filesystem::path& out_dir) {
  std::vector<Diagnostic> out;
  std::vector<std::pair<std::string, std::string>> files;  // name, bytes
  if (!read_assets(kWebAssetFiles, files, out)) return out;
  std::set<std::string> names;
  for (const auto& image : images) {
    if (!names.insert(web_image_name(image)).second)
      out.push_back(error_of(image.string(), "another image has the same name in the site: " + web_image_name(image)));
  }
  if (has_errors(out) || !make_dir(out_dir, out)) return out;
  for (const auto& [name, bytes] : files) {
    if (!write_or_report(out_dir / name, bytes, out)) return out;
  }
  std::string index = "{\"images\": [";
  bool first = true;
  for (const auto& image : images) {
    if (!write_image(image, options.actuator, out_dir, out)) continue;
    index += std::string(first ? "" : ", ") + json_string(web_image_name(image));
    first = false;
  }
  index += "]}\n";
  if (make_dir(out_dir / "images", out)) write_or_report(out_dir / "images" / "index.json", index, out);
  return out;
}

std::vector<Diagnostic> add_study_pages(const std::filesystem::path& out_dir) {
  std::vector<Diagnostic> out;
  std::vector<std::pair<std::string, std::string>> files;
  if (!read_assets(kStudyAssetFiles, files, out)) return out;
  for (const auto& [name, bytes] : files) {
    if (!write_or_report(out_dir / name, bytes, out)) break;
  }
  return out;
}

std::vector<Diagnostic> update_web_image(const std::filesystem::path& image, const WebSiteOptions& options,
                                         const std::filesystem::path& out_dir) {
  std::vector<Diagnostic> out;
  write_image(image, options.actuator, out_dir, out);
  return out;
}

std::optional<WebSiteOptions> web_site_options(const std::string& actuator_profile, std::vector<std::string>& errors) {
  if (actuator_profile.empty()) return WebSiteOptions{};
  ProfileLoadResult loaded = load_actuator_profile(actuator_profile);
  if (!loaded.profile) {
    for (std::string& e : loaded.errors) errors.push_back(std::move(e));
    return std::nullopt;
  }
  return WebSiteOptions{loaded.profile->response};
}

}  // namespace vimg
