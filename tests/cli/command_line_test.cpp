// Every `vimg` command follows the project's command-line conventions (cmdline/command_line.hpp):
// --help and --version exit 0 on stdout, usage errors exit 2 naming the command, numbers must be
// finite and in range.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cmdline/command_line.hpp"
#include "run_command.hpp"

namespace vimg {
namespace {

using test::CommandRun;

// Runs `PROGRAM ARGS` (a path below the build folder).
CommandRun run_program(const std::string& program, const std::string& args) {
  return test::run_command("'" VIMG_BINARY_DIR "/" + program + "' " + args);
}

CommandRun vimg(const std::string& args) { return run_program("cli/vimg", args); }

TEST(VimgConventions, HelpAndVersionExitZeroForEveryCommand) {
  for (const char* command : {"", "validate", "convert", "info", "render", "gesture", "gesture line", "gesture arc",
                              "gesture circle", "volume", "volume make-study", "volume probe"}) {
    const CommandRun help = vimg(std::string(command) + " --help");
    EXPECT_EQ(help.exit_code, 0) << command << "\n" << help.out;
    EXPECT_NE(help.out.find("Usage:"), std::string::npos) << command << "\n" << help.out;
  }
  for (const char* command : {"render", "validate", "volume probe"}) {
    EXPECT_NE(vimg(std::string(command) + " --help").out.find("Limits (docs/limits.md): "), std::string::npos) << command;
  }
  const CommandRun version = vimg("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out, std::string("vimg ") + cmdline::version() + "\n");
}

TEST(VimgConventions, UsageErrorsExitTwoAndNameTheCommand) {
  const CommandRun none = vimg("");
  EXPECT_EQ(none.exit_code, 2);
  const CommandRun unknown = vimg("frobnicate");
  EXPECT_EQ(unknown.exit_code, 2);
  const CommandRun missing = vimg("render image.vimg --out x.wav");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.out.find("vimg render: error: --gesture is required"), std::string::npos) << missing.out;
  EXPECT_NE(missing.out.find("Run 'vimg render --help'"), std::string::npos) << missing.out;
  EXPECT_EQ(vimg("render image.vimg --gesture g.csv --out x.mp3").exit_code, 2);
  EXPECT_EQ(vimg("render image.vimg --gesture g.csv --out x.wav --rate 0").exit_code, 2);
  EXPECT_EQ(vimg("render image.vimg --gesture g.csv --out x.wav --rate 8000.5").exit_code, 2);
  EXPECT_EQ(vimg("volume make-study --seed -3 --out d").exit_code, 2);
  EXPECT_EQ(vimg("volume probe scene.xml --out f.csv").exit_code, 2);
}

TEST(VimgConventions, NumbersMustBeFiniteAndInRange) {
  for (const char* bad : {"nan", "inf", "-inf", "1e999", "5,5", "", "0x10"}) {
    const CommandRun r = vimg(std::string("gesture line --from 0,0 --to 10,0 --out g.csv --speed '") + bad + "'");
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.out;
  }
  const CommandRun point = vimg("gesture line --from 0,nan --to 10,0 --out g.csv");
  EXPECT_EQ(point.exit_code, 2);
  EXPECT_NE(point.out.find("not X,Y with two finite numbers"), std::string::npos) << point.out;
  EXPECT_EQ(vimg("gesture line --from 0,0 --to 10,0 --out g.csv --pressure 1.5").exit_code, 2);
  EXPECT_EQ(vimg("gesture circle --center 0,0 --radius -1 --out g.csv").exit_code, 2);
}

// Every program of the project, where this build has it (the sanitizer builds leave out the GUI).
TEST(ProgramConventions, EveryProgramAnswersHelpVersionAndUsageErrorsAlike) {
  int checked = 0;
  for (const char* program : {"cli/vimg", "editor/vimg-editor", "apps/probe/vimg-probe", "apps/vimg-player/vimg-player",
                              "apps/force/vimg-force"}) {
    if (!std::filesystem::exists(std::string(VIMG_BINARY_DIR "/") + program)) continue;
    ++checked;
    const std::string name = std::filesystem::path(program).filename().string();
    const CommandRun help = run_program(program, "--help");
    EXPECT_EQ(help.exit_code, 0) << name;
    EXPECT_NE(help.out.find("Usage: " + name), std::string::npos) << help.out;
    const CommandRun version = run_program(program, "--version");
    EXPECT_EQ(version.exit_code, 0) << name;
    EXPECT_EQ(version.out, name + " " + cmdline::version() + "\n");
    const CommandRun unknown = run_program(program, "--no-such-option");
    EXPECT_EQ(unknown.exit_code, 2) << name << "\n" << unknown.out;
    EXPECT_EQ(unknown.out.rfind(name + ": error: ", 0), 0u) << unknown.out;
  }
  if (checked == 0) GTEST_SKIP() << "no program built";
}

TEST(ProgramConventions, ProbeRefusesEndlessFramesAndNonFiniteMoves) {
  const std::string probe = "apps/probe/vimg-probe";
  if (!std::filesystem::exists(std::string(VIMG_BINARY_DIR "/") + probe)) GTEST_SKIP() << "no GUI in this build";
  EXPECT_EQ(run_program(probe, "scene.xml --frames -1").exit_code, 2);
  EXPECT_EQ(run_program(probe, "scene.xml --frames 0").exit_code, 2);
  EXPECT_EQ(run_program(probe, "scene.xml --frames 3 --move nan,1").exit_code, 2);
  EXPECT_EQ(run_program(probe, "scene.xml --move 1,1").exit_code, 2);  // --move needs --frames
  EXPECT_EQ(run_program(probe, "scene.xml --path p.csv").exit_code, 2);  // --path needs --device sim
  EXPECT_EQ(run_program(probe, "scene.xml --device hid --path p.csv").exit_code, 2);
  EXPECT_EQ(run_program(probe, "scene.xml --device usb").exit_code, 2);
  EXPECT_EQ(run_program(probe, "scene.xml --device sim --frames 2 --move 1,1").exit_code, 2);
}

TEST(ProgramConventions, PlayerExitsOneAtOnceWhenItsWavOutputCannotBeWritten) {
  const std::string player = "apps/vimg-player/vimg-player";
  if (!std::filesystem::exists(std::string(VIMG_BINARY_DIR "/") + player)) GTEST_SKIP() << "no GUI in this build";
  const CommandRun r = test::run_command("SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy timeout 20 '" VIMG_BINARY_DIR "/" + player +
                                         "' '" VIMG_SOURCE_DIR "/assets/examples/smiley.vimg' --window 400x300 "
                                         "--output wav:/nonexistent-folder/out.wav");
  EXPECT_EQ(r.exit_code, 1) << r.out;  // not 124 (still running at the timeout), not 0
  EXPECT_NE(r.out.find("/nonexistent-folder/out.wav: cannot create a temporary file next to it"), std::string::npos) << r.out;
}

TEST(ProgramConventions, EditorRefusesBadNumbers) {
  const std::string editor = "editor/vimg-editor";
  if (!std::filesystem::exists(std::string(VIMG_BINARY_DIR "/") + editor)) GTEST_SKIP() << "no GUI in this build";
  for (const char* bad : {"--rate nan", "--zoom inf", "--size 10x10", "--px-per-mm -1", "--output bogus:1",
                          "--autosave-interval 0"}) {
    EXPECT_EQ(run_program(editor, bad).exit_code, 2) << bad;
  }
}

}  // namespace
}  // namespace vimg
