// `vimg validate FILE...` (spec section 4): checks .vimg and .png files.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "storage/image_io.hpp"
#include "storage/limits.hpp"

namespace vimg::cli {

namespace {

int run_validate(const std::vector<std::string>& files) {
  bool all_valid = true;
  for (const std::string& arg : files) {
    const LoadResult result = load_image_file(arg);
    for (const Diagnostic& d : result.diagnostics) std::printf("%s\n", d.to_string().c_str());
    if (result.ok()) {
      std::printf("%s: ok\n", arg.c_str());
    } else {
      all_valid = false;
    }
  }
  std::fflush(stdout);
  return all_valid ? kExitOk : kExitFailure;
}

}  // namespace

void add_validate_command(CLI::App& vimg, int& exit_code) {
  CLI::App* sub = vimg.add_subcommand("validate", "check .vimg and .png images; exit 1 if any is invalid");
  auto files = std::make_shared<std::vector<std::string>>();
  sub->add_option("FILE", *files, "images to check")->required();
  sub->footer("Limits (docs/limits.md): " + std::to_string(kMaxImageFileBytes >> 20) + " MiB per file, " +
              std::to_string(kMaxAttributesPerElement) + " attributes per element, nesting " +
              std::to_string(kMaxXmlNestingDepth) + " deep, " + std::to_string(kMaxPolygonPoints) +
              " points per polygon; the first " + std::to_string(kMaxDiagnosticsPerFile) + " problems of a file are listed.");
  sub->callback([files, &exit_code] { exit_code = run_validate(*files); });
}

}  // namespace vimg::cli
