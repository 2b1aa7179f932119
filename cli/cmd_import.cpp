// `vimg import DRAWING.svg|PICTURE.png --out IMAGE.(vimg|xml|png)` (docs/import.md): a drawing or a
// picture made with another tool becomes a vibroimage, written atomically.
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/command.hpp"
#include "hal/rest_on_exit.hpp"
#include "storage/image_io.hpp"
#include "storage/import/import.hpp"
#include "storage/limits.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::cli {

namespace {

struct ImportArgs {
  std::string input;
  std::string out;
  double mm_per_unit = 0.0;  // 0: from the SVG's units
  double width_mm = 0.0;     // 0: not given
  int levels = 4;
};

int run_import(const ImportArgs& a) {
  ImportOptions options;
  if (a.mm_per_unit > 0.0) options.mm_per_unit = a.mm_per_unit;
  if (a.width_mm > 0.0) options.width_mm = a.width_mm;
  options.levels = a.levels;
  // SIGINT/SIGTERM only set a flag: the import finishes its step, nothing is written, exit 130/143.
  const SignalRestScope signals;
  const auto interrupted = [&] {
    std::fprintf(stderr, "vimg import: interrupted; %s not written\n", a.out.c_str());
    return rest_signal() == SIGTERM ? cmdline::kExitSigterm : cmdline::kExitSigint;
  };
  const ImportResult r = import_file(a.input, options);
  if (rest_requested()) return interrupted();
  print_diagnostics(r.diagnostics);
  if (!r.ok()) return kExitFailure;
  if (r.opened_vibroimage) {
    std::fprintf(stderr, "%s: this PNG already holds a vibroimage: opened as one, not imported as a picture\n",
                 a.input.c_str());
  }
  if (rest_requested()) return interrupted();
  SaveOptions save;
  save.new_file_mode = NewFileMode::of(a.input);  // a new output takes the input's permission bits, as cp's copy
  if (const auto error = save_image_file(*r.image, a.out, save)) {
    std::fprintf(stderr, "vimg import: %s\n", error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void add_import_command(CLI::App& vimg, int& exit_code) {
  CLI::App* sub = vimg.add_subcommand("import", "import an SVG drawing or a PNG picture as a vibroimage");
  auto a = std::make_shared<ImportArgs>();
  sub->add_option("INPUT", a->input, "DRAWING.svg or PICTURE.png")->required();
  sub->add_option("--out", a->out, "the image to write (.vimg/.xml, or .png with the XML inside), atomically")->required();
  sub->add_option("--mm-per-unit", a->mm_per_unit, "SVG: mm per user unit (default: from width, height and viewBox)")
      ->check(cmdline::finite_in(1e-6, kMaxCanvasMm));
  sub->add_option("--width-mm", a->width_mm, "picture: the canvas width in mm (required for a picture)")
      ->check(cmdline::finite_in(1e-3, kMaxCanvasMm));
  sub->add_option("--levels", a->levels, "picture: grey levels, darker = stronger gain (default 4)")
      ->check(CLI::Range(1, kMaxPictureLevels));
  sub->footer("SVG: shapes, paths, groups and transforms become DOT/LINE/SURFACE primitives; text, pictures, "
              "gradients and the like are listed as warnings. PNG: one SURFACE polygon per region of a grey level. "
              "A PNG that already holds a vibroimage is opened, not imported. Limits (docs/limits.md): " +
              std::to_string(kMaxImageFileBytes >> 20) + " MiB per file, " + std::to_string(kMaxPolygonPoints) +
              " points per polygon, a picture of at most " + std::to_string(static_cast<long long>(kMaxPngPixels)) +
              " pixels. See docs/import.md.");
  sub->callback([a, &exit_code] {
    exit_code = run_import(*a);
  });
}

}  // namespace vimg::cli
