// `vimg validate FILE...` (spec section 4): checks .vimg and .png files.
#include <cstdio>
#include <span>
#include <string>
#include <string_view>

#include "cli/command.hpp"
#include "storage/image_io.hpp"

namespace vimg::cli {

int run_validate(std::span<const std::string_view> args) {
  if (args.empty()) {
    std::fprintf(stderr, "usage: vimg validate FILE...\n");
    return kExitUsage;
  }
  for (const auto arg : args) {
    if (arg.size() > 1 && arg.front() == '-') {
      std::fprintf(stderr, "vimg validate: unknown option '%.*s'\nusage: vimg validate FILE...\n",
                   static_cast<int>(arg.size()), arg.data());
      return kExitUsage;
    }
  }
  bool all_valid = true;
  for (const auto arg : args) {
    const LoadResult result = load_image_file(std::string(arg));
    for (const Diagnostic& d : result.diagnostics) std::printf("%s\n", d.to_string().c_str());
    if (result.ok()) {
      std::printf("%.*s: ok\n", static_cast<int>(arg.size()), arg.data());
    } else {
      all_valid = false;
    }
  }
  std::fflush(stdout);
  return all_valid ? kExitOk : kExitFailure;
}

}  // namespace vimg::cli
