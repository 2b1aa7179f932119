// `vimg convert IN OUT [--scale PX_PER_MM]` (spec section 4): .vimg <-> .png by extension.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "cli/command.hpp"
#include "storage/image_io.hpp"
#include "storage/number_text.hpp"

namespace vimg::cli {

namespace {

constexpr const char* kConvertUsage = "usage: vimg convert IN OUT [--scale PX_PER_MM]\n";

bool has_extension(const std::filesystem::path& path, std::string_view ext) {
  std::string e = path.extension().string();
  for (char& c : e) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return e == ext;
}

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true;
  return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
}

}  // namespace

int run_convert(std::span<const std::string_view> args) {
  std::vector<std::string_view> positional;
  SaveOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--scale") {
      if (i + 1 >= args.size()) {
        std::fprintf(stderr, "vimg convert: --scale needs a value\n%s", kConvertUsage);
        return kExitUsage;
      }
      const ParsedNumber scale = parse_decimal(args[++i]);
      if (const auto* reason = std::get_if<std::string>(&scale)) {
        std::fprintf(stderr, "vimg convert: --scale \"%.*s\" %s\n", static_cast<int>(args[i].size()), args[i].data(),
                     reason->c_str());
        return kExitUsage;
      }
      options.scale_px_per_mm = std::get<double>(scale);
      if (!(options.scale_px_per_mm > 0.0)) {
        std::fprintf(stderr, "vimg convert: --scale must be > 0 pixels per mm\n");
        return kExitUsage;
      }
    } else if (args[i].size() > 1 && args[i].front() == '-') {
      std::fprintf(stderr, "vimg convert: unknown option '%.*s'\n%s", static_cast<int>(args[i].size()),
                   args[i].data(), kConvertUsage);
      return kExitUsage;
    } else {
      positional.push_back(args[i]);
    }
  }
  if (positional.size() != 2) {
    std::fprintf(stderr, "%s", kConvertUsage);
    return kExitUsage;
  }
  const std::filesystem::path in(positional[0]);
  const std::filesystem::path out(positional[1]);
  if (!has_extension(out, ".vimg") && !has_extension(out, ".png")) {
    std::fprintf(stderr, "vimg convert: %s: the output must end in .vimg or .png\n", out.c_str());
    return kExitFailure;
  }
  if (same_file(in, out)) {
    std::fprintf(stderr, "vimg convert: %s: refusing to overwrite the input file\n", out.c_str());
    return kExitFailure;
  }
  const LoadResult loaded = load_image_file(in);
  for (const Diagnostic& d : loaded.diagnostics) std::fprintf(stderr, "%s\n", d.to_string().c_str());
  if (!loaded.ok()) {
    std::fprintf(stderr, "vimg convert: %s is not a valid image; nothing written\n", in.c_str());
    return kExitFailure;
  }
  if (const auto error = save_image_file(*loaded.image, out, options)) {
    std::fprintf(stderr, "vimg convert: %s\n", error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace vimg::cli
