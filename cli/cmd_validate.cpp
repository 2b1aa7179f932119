// `vimg validate FILE... [--actuator P]` (spec section 4): checks .vimg and .png files; with an
// actuator profile, also warns about textures the actuator will barely render (docs/actuators.md).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/felt_report.hpp"
#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::cli {

namespace {

struct ValidateArgs {
  std::vector<std::string> files;
  std::string actuator;  // profile; empty: no check of the feel
};

int run_validate(const ValidateArgs& a) {
  std::unique_ptr<FeltAnalysis> felt;
  if (!a.actuator.empty()) {
    felt = load_felt_analysis(a.actuator);
    if (!felt) return kExitFailure;
  }
  bool all_valid = true;
  for (const std::string& arg : a.files) {
    const LoadResult result = load_image_file(arg);
    print_diagnostics(result.diagnostics, stdout);
    if (result.ok() && felt) {
      DiagnosticList warnings(arg, DiagnosticList::Order::by_line);
      add_felt_warnings(*result.image, *felt, warnings);
      print_diagnostics(warnings.take(), stdout);
    }
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
  auto a = std::make_shared<ValidateArgs>();
  sub->add_option("FILE", a->files, "images to check")->required();
  sub->add_option("--actuator", a->actuator,
                  "actuator profile: a file, or a shipped profile's name (lra-175hz-drv2605l, erm-10mm, voice-coil-audio, ideal): also warn about every SURFACE and LINE whose frequency at "
                  "fullSpeed is more than 10 dB below the actuator's peak response (warnings keep exit 0)");
  sub->footer("Limits (docs/limits.md): " + std::to_string(kMaxImageFileBytes >> 20) + " MiB per file, " +
              std::to_string(kMaxXmlElements) + " elements and " + std::to_string(kMaxXmlAttributes) +
              " attributes per file, " + std::to_string(kMaxAttributesPerElement) + " attributes per element (" +
              std::to_string(kMaxUnknownAttributesPerElement) + " unknown ones kept), nesting " +
              std::to_string(kMaxXmlNestingDepth) + " deep, " + std::to_string(kMaxPolygonPoints) +
              " points per polygon; the first " + std::to_string(kMaxDiagnosticsPerFile) + " problems of a file are listed.");
  sub->callback([a, &exit_code] { exit_code = run_validate(*a); });
}

}  // namespace vimg::cli
