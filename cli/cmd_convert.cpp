// `vimg convert IN OUT [--scale PX_PER_MM]` (spec section 4): .vimg <-> .png by extension.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>

#include "cli/command.hpp"
#include "storage/image_io.hpp"
#include "storage/file_extension.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::cli {

namespace {

bool has_extension(const std::filesystem::path& path, std::string_view ext) { return lower_extension(path) == ext; }

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true;
  return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
}

int run_convert(const std::string& in_file, const std::string& out_file, double scale_px_per_mm) {
  SaveOptions options;
  options.scale_px_per_mm = scale_px_per_mm;
  const std::filesystem::path in(in_file);
  options.new_file_mode = NewFileMode::of(in);  // a new output takes the input's permission bits, as cp's copy
  const std::filesystem::path out(out_file);
  if (!has_extension(out, ".vimg") && !has_extension(out, ".png")) {
    std::fprintf(stderr, "vimg convert: %s: the output must end in .vimg or .png\n", out.c_str());
    return kExitFailure;
  }
  if (same_file(in, out)) {
    std::fprintf(stderr, "vimg convert: %s: refusing to overwrite the input file\n", out.c_str());
    return kExitFailure;
  }
  const LoadResult loaded = load_image_file(in);
  print_diagnostics(loaded.diagnostics);
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

}  // namespace

void add_convert_command(CLI::App& vimg, int& exit_code) {
  CLI::App* sub = vimg.add_subcommand("convert", "convert .vimg <-> .png by extension; never overwrites IN");
  struct Args {
    std::string in, out;
    double scale_px_per_mm = SaveOptions{}.scale_px_per_mm;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("IN", a->in, "the image to read (.vimg or .png)")->required();
  sub->add_option("OUT", a->out, "the image to write (.vimg or .png), written atomically")->required();
  sub->add_option("--scale", a->scale_px_per_mm, "PNG picture scale in pixels per mm")
      ->check(cmdline::finite_in(1e-3, 1000.0));
  sub->callback([a, &exit_code] { exit_code = run_convert(a->in, a->out, a->scale_px_per_mm); });
}

}  // namespace vimg::cli
