// A new file that a command derives from another takes that file's permission bits, less the
// umask, as cp's copy does (`vimg convert private.vimg copy.vimg` with a 0600 input gave a 0644
// output); a destination that exists keeps its own. Every command that derives one file from
// another: convert, import, render (and its register trace), gesture import and merge, volume probe.
// An output made from several files (compare, study report) takes the bits they all share.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";
const fs::path kData = VIMG_TEST_DATA_DIR;
const fs::path kSource = VIMG_SOURCE_DIR;

class DerivedFileMode : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_mode_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A copy of `from` in the folder as `name`, with permission bits `mode`.
  std::string input(const fs::path& from, const std::string& name, fs::perms mode) {
    fs::copy_file(from, dir_ / name, fs::copy_options::overwrite_existing);
    fs::permissions(dir_ / name, mode);
    return name;
  }
  // Runs vimg in the folder under umask `umask_octal`; expects exit 0.
  void vimg(const std::string& arguments, const std::string& umask_octal = "022") {
    const test::CommandRun r =
        test::run_command("cd '" + dir_.string() + "' && umask " + umask_octal + " && '" + kVimg + "' " + arguments);
    ASSERT_EQ(r.exit_code, 0) << arguments << "\n" << r.out;
  }
  fs::perms mode_of(const std::string& name) const { return fs::status(dir_ / name).permissions() & fs::perms::all; }

  fs::path dir_;
};

constexpr fs::perms kPrivate = fs::perms::owner_read | fs::perms::owner_write;  // 0600
constexpr fs::perms kGroupRead = kPrivate | fs::perms::group_read;            // 0640
constexpr fs::perms kShared = kGroupRead | fs::perms::others_read;            // 0644

TEST_F(DerivedFileMode, ConvertGivesANewOutputTheInputsBits) {
  input(kData / "valid" / "smiley.vimg", "private.vimg", kPrivate);
  vimg("convert private.vimg copy.vimg");
  EXPECT_EQ(mode_of("copy.vimg"), kPrivate);
  vimg("convert private.vimg copy.png");
  EXPECT_EQ(mode_of("copy.png"), kPrivate);
  input(kData / "valid" / "smiley.vimg", "group.vimg", kGroupRead);
  vimg("convert group.vimg group.png");
  EXPECT_EQ(mode_of("group.png"), kGroupRead);
  // The umask still applies, as to cp's copy: 0755 under umask 027 is 0750.
  input(kData / "valid" / "smiley.vimg", "script.vimg", fs::perms::owner_all | fs::perms::group_all | fs::perms::others_read |
                                                            fs::perms::others_exec);
  vimg("convert script.vimg masked.vimg", "027");
  EXPECT_EQ(mode_of("masked.vimg"), fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
}

TEST_F(DerivedFileMode, AnExistingDestinationKeepsItsOwnBits) {
  input(kData / "valid" / "smiley.vimg", "private.vimg", kPrivate);
  input(kData / "valid" / "defaults.vimg", "shared.vimg", kShared);
  vimg("convert private.vimg shared.vimg");
  EXPECT_EQ(mode_of("shared.vimg"), kShared);
  input(kData / "valid" / "defaults.vimg", "private-target.vimg", kPrivate);
  input(kData / "valid" / "smiley.vimg", "open.vimg", kShared);
  vimg("convert open.vimg private-target.vimg");
  EXPECT_EQ(mode_of("private-target.vimg"), kPrivate);
}

TEST_F(DerivedFileMode, ImportGivesANewImageTheDrawingsOrPicturesBits) {
  input(kSource / "tests" / "import" / "data" / "adwaita-folder-48.png", "picture.png", kPrivate);
  vimg("import picture.png --out picture.vimg --width-mm 20");
  EXPECT_EQ(mode_of("picture.vimg"), kPrivate);
  input(kSource / "tests" / "import" / "data" / "adwaita-parental-controls.svg", "drawing.svg", kGroupRead);
  vimg("import drawing.svg --out drawing.png");
  EXPECT_EQ(mode_of("drawing.png"), kGroupRead);
}

TEST_F(DerivedFileMode, RenderGivesEveryNewOutputTheImagesBits) {
  input(kData / "valid" / "smiley.vimg", "private.vimg", kPrivate);
  input(kSource / "assets" / "gestures" / "smiley_eyes.csv", "g.csv", kShared);
  for (const std::string out : {"drive.wav", "drive.csv", "clip.ahap", "clip.haptic"}) {
    vimg("render private.vimg --gesture g.csv --out " + out);
    EXPECT_EQ(mode_of(out), kPrivate) << out;
  }
  vimg("render private.vimg --gesture g.csv --out traced.wav --actuator '" +
       (kSource / "assets" / "profiles" / "lra-175hz-drv2605l.xml").string() + "' --register-trace trace.csv");
  EXPECT_EQ(mode_of("traced.wav"), kPrivate);
  EXPECT_EQ(mode_of("trace.csv"), kPrivate);
}

TEST_F(DerivedFileMode, GestureImportAndMergeGiveTheirSourcesBits) {
  input(kData / "evdev" / "atmel-maxtouch.2-fingers-touch-release.evemu", "touches.evemu", kPrivate);
  vimg("gesture import touches.evemu --panel-mm 154x92.4 --out touches.csv");
  EXPECT_EQ(mode_of("touches.csv"), kPrivate);
  vimg("gesture line --from 10,10 --to 50,10 --speed 100 --finger 3 --merge touches.csv --out merged.csv");
  EXPECT_EQ(mode_of("merged.csv"), kPrivate);
  // Synthesised from nothing: 0666 less the umask.
  vimg("gesture line --from 10,10 --to 50,10 --speed 100 --out synthesised.csv");
  EXPECT_EQ(mode_of("synthesised.csv"), kShared);
}

TEST_F(DerivedFileMode, VolumeProbeGivesTheScenesBits) {
  vimg("volume make-study --seed 1 --out S");
  fs::permissions(dir_ / "S" / "study.vscene.xml", kGroupRead);
  std::ofstream(dir_ / "P.csv") << "time_s,x_mm,y_mm,z_mm\n0,-70,-20,-50\n0.05,70,20,50\n";
  vimg("volume probe S/study.vscene.xml --path P.csv --out F.csv");
  EXPECT_EQ(mode_of("F.csv"), kGroupRead);
}

TEST_F(DerivedFileMode, CompareAndStudyReportTakeTheBitsEveryInputShares) {
  input(kData / "compare" / "dot.vimg", "dot.vimg", kShared);
  input(kData / "compare" / "line.vimg", "line.vimg", kGroupRead);
  vimg("compare dot.vimg line.vimg --out predicted.json");
  EXPECT_EQ(mode_of("predicted.json"), kGroupRead);
  input(kData / "compare" / "surface.vimg", "surface.vimg", kPrivate);
  vimg("compare dot.vimg line.vimg surface.vimg --out private.html");
  EXPECT_EQ(mode_of("private.html"), kPrivate);

  // Two participants' trial files; one of them private.
  const std::string header = "participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc\n";
  std::ofstream(dir_ / "P01.trials.csv") << header << "P01,a,1,dot,dot,1,2.5,1.0,120,2026-11-25T16:38:51Z\n"
                                         << "P01,a,2,line,line,1,2.5,1.0,120,2026-11-25T16:39:51Z\n";
  std::ofstream(dir_ / "P02.trials.csv") << header << "P02,a,1,line,dot,0,2.5,1.0,120,2026-11-25T16:38:51Z\n"
                                         << "P02,a,2,dot,dot,1,2.5,1.0,120,2026-11-25T16:39:51Z\n";
  fs::permissions(dir_ / "P01.trials.csv", kShared);
  fs::permissions(dir_ / "P02.trials.csv", kGroupRead);
  vimg("study report P01.trials.csv P02.trials.csv --out report.md");
  EXPECT_EQ(mode_of("report.md"), kGroupRead);
  fs::permissions(dir_ / "P01.trials.csv", kPrivate);
  vimg("study report P01.trials.csv P02.trials.csv --predicted predicted.json --out report.json");
  EXPECT_EQ(mode_of("report.json"), kPrivate);
}

TEST_F(DerivedFileMode, SeparateGivesEachProposalItsImagesBitsAndTheReportTheShared) {
  // Two copies of one texture: confused, so both are proposed anew.
  input(kData / "compare" / "surface.vimg", "a.vimg", kGroupRead);
  input(kData / "compare" / "surface.vimg", "b.vimg", kPrivate);
  vimg("separate a.vimg b.vimg --out P");
  EXPECT_EQ(mode_of("P/a.vimg"), kGroupRead);
  EXPECT_EQ(mode_of("P/b.vimg"), kPrivate);
  EXPECT_EQ(mode_of("P/separate.json"), kPrivate);
  EXPECT_EQ(mode_of("P/separate.html"), kPrivate);
}

}  // namespace
}  // namespace vimg
