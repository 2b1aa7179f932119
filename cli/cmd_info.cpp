// `vimg info FILE [--actuator P]` (spec section 4): size, counts per primitive kind, groups, meta;
// with an actuator profile, each primitive's frequency at fullSpeed and the actuator's response there.
#include <cstdio>
#include <memory>
#include <string>

#include "cli/command.hpp"
#include "cli/felt_report.hpp"
#include "storage/image_io.hpp"
#include "storage/image_summary.hpp"
#include "storage/number_text.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::cli {

namespace {

void print_field(const char* label, const std::optional<std::string>& value) {
  if (value) std::printf("%-13s %s\n", label, value->c_str());
}

int run_info(const std::string& file, const std::string& actuator) {
  std::unique_ptr<FeltAnalysis> felt;
  if (!actuator.empty()) {
    felt = load_felt_analysis(actuator);
    if (!felt) return kExitFailure;
  }
  const LoadResult loaded = load_image_file(file);
  print_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) return kExitFailure;
  const Image& image = *loaded.image;
  const ImageSummary s = summarize(image);
  std::printf("%-13s %s\n", "file:", file.c_str());
  std::printf("%-13s %d.%d\n", "version:", image.version_major, image.version_minor);
  std::printf("%-13s %s x %s mm\n", "size:", format_decimal(image.width_mm).c_str(),
              format_decimal(image.height_mm).c_str());
  std::printf("%-13s %d (dots %d, lines %d, surfaces %d)\n", "primitives:", s.primitives(), s.dots, s.lines,
              s.surfaces);
  std::printf("%-13s %d (deepest nesting %d)\n", "groups:", s.groups, s.max_group_depth);
  if (s.unknown_elements > 0) std::printf("%-13s %d (kept as is)\n", "unknown:", s.unknown_elements);
  const InteractionParams p = image.effective_interaction();
  std::printf("%-13s mass %s kg, fullSpeed %s mm/s, maxDeformation %s mm%s\n", "interaction:",
              format_decimal(p.mass_kg).c_str(), format_decimal(p.full_speed_mm_per_s).c_str(),
              format_decimal(p.max_deformation_mm).c_str(), image.interaction ? "" : " (defaults)");
  if (image.meta) {
    const Meta& m = *image.meta;
    print_field("title:", m.title);
    print_field("author:", m.author);
    print_field("description:", m.description);
    print_field("created:", m.created);
    if (!m.tags.empty()) {
      std::string tags;
      for (const auto& t : m.tags) tags += (tags.empty() ? "" : ", ") + t;
      std::printf("%-13s %s\n", "tags:", tags.c_str());
    }
    if (m.tool) std::printf("%-13s %s %s\n", "tool:", m.tool->name.c_str(), m.tool->version.c_str());
  } else {
    std::printf("%-13s none\n", "meta:");
  }
  if (felt) print_felt_table(image, *felt);
  return kExitOk;
}

}  // namespace

void add_info_command(CLI::App& vimg, int& exit_code) {
  CLI::App* sub = vimg.add_subcommand("info", "summary: size, primitives per kind, groups, meta");
  auto file = std::make_shared<std::string>();
  auto actuator = std::make_shared<std::string>();
  sub->add_option("FILE", *file, "a .vimg or .png image")->required();
  sub->add_option("--actuator", *actuator,
                  "actuator profile: a file, or a shipped profile's name (lra-175hz-drv2605l, erm-10mm, voice-coil-audio, ideal): list each primitive's frequency at fullSpeed and the "
                  "actuator's response there in dB re its peak");
  sub->callback([file, actuator, &exit_code] { exit_code = run_info(*file, *actuator); });
}

}  // namespace vimg::cli
