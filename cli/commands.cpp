#include "cli/command.hpp"

#include <array>

namespace vimg::cli {

// Each command's entry point, defined in its own cli/cmd_*.cpp.
int run_validate(std::span<const std::string_view> args);
int run_convert(std::span<const std::string_view> args);
int run_info(std::span<const std::string_view> args);
int render_command(std::span<const std::string_view> args);
int gesture_command(std::span<const std::string_view> args);
int volume_command(std::span<const std::string_view> args);

std::span<const Command> all_commands() {
  static const Command commands[] = {
      {"validate", "vimg validate FILE...", "check .vimg and .png images; exit 1 if any is invalid", run_validate},
      {"convert", "vimg convert IN OUT [--scale PX_PER_MM]", "convert .vimg <-> .png (default 10 px/mm)",
       run_convert},
      {"info", "vimg info FILE", "summary: size, primitives per kind, groups, meta", run_info},
      {"render", "vimg render IMAGE --gesture G.csv --out OUT.(wav|csv) [--rate HZ]",
       "render the drive signal of a gesture over an image (mono float WAV or time_s,drive CSV)", render_command},
      {"gesture", "vimg gesture (line|arc|circle) ... --out G.csv",
       "synthesise a gesture file from a path at a given speed and event rate", gesture_command},
      {"volume", "vimg volume (make-study --seed N --out DIR | probe SCENE --path P.csv --out F.csv)",
       "volume haptics: write the study data set, or render forces along a probe path", volume_command},
  };
  return commands;
}

}  // namespace vimg::cli
