// `vimg study fit` and `vimg compare --model` refuse bad input with a clear error and change
// nothing: a trial file of another study, a location trial file, no trials, one participant, too
// few trials to fit, and a model file that is malformed or of a newer version.
#include <gtest/gtest.h>

#include <string>

#include "tests/cli/run_command.hpp"
#include "tests/study_fit/fit_files.hpp"

namespace vimg::fit_test {
namespace {

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";
constexpr const char* kHeader = "participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc\n";

std::string row(const std::string& participant, const std::string& set, int trial, const std::string& presented,
                const std::string& chosen) {
  return participant + "," + set + "," + std::to_string(trial) + "," + presented + "," + chosen + "," +
         (presented == chosen ? "1" : "0") + ",1.5,0.5,40,2026-11-27T10:00:00Z\n";
}

// `trials` trials of `participant` in set "textures" over images a, b, c, every fourth one wrong.
std::string trials_of(const std::string& participant, int trials) {
  std::string text = kHeader;
  const char* images[] = {"a", "b", "c"};
  for (int k = 1; k <= trials; ++k) {
    const std::string presented = images[k % 3];
    text += row(participant, "textures", k, presented, k % 4 == 0 ? images[(k + 1) % 3] : presented);
  }
  return text;
}

class FitCommand : public FitFolderTest {
 protected:
  void SetUp() override {
    FitFolderTest::SetUp();
    write_surface_study(dir_, "textures", {{"a", 2.0, 0.7}, {"b", 3.0, 0.7}, {"c", 2.0, 0.3}}, 5, 20.0);
    std::ofstream(dir_ / "model.json") << "the old model\n";
  }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name, std::ios::binary) << text; }
  test::CommandRun vimg(const std::string& arguments) {
    return test::run_command("cd '" + dir_.string() + "' && timeout 120 '" + kVimg + "' " + arguments);
  }
  test::CommandRun fit(const std::string& trial_files) {
    return vimg("study fit " + trial_files + " --study study.xml --out model.json");
  }
  void expect_model_unchanged() { EXPECT_EQ(read_text(dir_ / "model.json"), "the old model\n"); }
};

TEST_F(FitCommand, ATrialFileOfAnotherStudyIsNamedAtItsFirstForeignRow) {
  write("p1.trials.csv", trials_of("p1", 40));
  write("other.trials.csv", std::string(kHeader) + row("q1", "textures", 1, "a", "a") + row("q1", "shapes", 2, "dot", "line"));
  const test::CommandRun r = fit("p1.trials.csv other.trials.csv");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("other.trials.csv:3: error: set 'shapes' is not a set of study.xml (its sets: textures): a trial file "
                       "of another study?"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("vimg study fit: model.json not written"), std::string::npos) << r.out;
  expect_model_unchanged();

  write("image.trials.csv", std::string(kHeader) + row("q2", "textures", 1, "a", "house"));
  const test::CommandRun image = fit("p1.trials.csv image.trials.csv");
  EXPECT_EQ(image.exit_code, 1);
  EXPECT_NE(image.out.find("image.trials.csv:2: error: image 'house' is not in set 'textures' of study.xml (its images: a, b, "
                           "c): a trial file of another study?"),
            std::string::npos)
      << image.out;
  expect_model_unchanged();
}

TEST_F(FitCommand, ALocationTrialFileAndATrialGivenTwiceAreErrors) {
  write("p1.trials.csv", trials_of("p1", 40));
  write("l1.location.csv",
        "participant,trial,metaphor,seed,target_x_mm,target_z_mm,mark_x_mm,mark_y_mm,mark_z_mm,error_mm,explore_s,time_utc\n");
  const test::CommandRun location = fit("p1.trials.csv l1.location.csv");
  EXPECT_EQ(location.exit_code, 1);
  EXPECT_NE(location.out.find("l1.location.csv:1: error: a trial file of the location study"), std::string::npos) << location.out;
  const test::CommandRun twice = fit("p1.trials.csv p1.trials.csv");
  EXPECT_EQ(twice.exit_code, 1);
  EXPECT_NE(twice.out.find("p1.trials.csv:2: error: participant 'p1' trial 1 is also at p1.trials.csv:2"), std::string::npos)
      << twice.out;
  expect_model_unchanged();
}

TEST_F(FitCommand, NoTrialsOneParticipantAndTooFewTrialsAreRefused) {
  write("empty1.trials.csv", kHeader);
  write("empty2.trials.csv", kHeader);
  const test::CommandRun none = fit("empty1.trials.csv empty2.trials.csv");
  EXPECT_EQ(none.exit_code, 1);
  EXPECT_NE(none.out.find("vimg study fit: error: the trial files hold no trials of the study's sets: nothing to fit; "
                          "model.json not written"),
            std::string::npos)
      << none.out;

  write("p1.trials.csv", trials_of("p1", 60));
  const test::CommandRun one = fit("p1.trials.csv");
  EXPECT_EQ(one.exit_code, 1);
  EXPECT_NE(one.out.find("error: the trials are of one participant only (p1): the fit is judged by leaving one participant "
                         "out, which needs at least two"),
            std::string::npos)
      << one.out;

  write("p2.trials.csv", trials_of("p2", 3));
  write("p3.trials.csv", trials_of("p3", 3));
  const test::CommandRun few = fit("p2.trials.csv p3.trials.csv");
  EXPECT_EQ(few.exit_code, 1);
  EXPECT_NE(few.out.find("error: 6 trials for "), std::string::npos) << few.out;
  EXPECT_NE(few.out.find("at least 10 trials per constant"), std::string::npos) << few.out;
  expect_model_unchanged();
}

TEST_F(FitCommand, UsageErrorsExit2) {
  write("p1.trials.csv", trials_of("p1", 40));
  EXPECT_EQ(vimg("study fit p1.trials.csv --study study.xml --out model.txt").exit_code, 2);
  EXPECT_EQ(vimg("study fit p1.trials.csv --study study.xml --out p1.trials.csv").exit_code, 2);
  EXPECT_EQ(vimg("study fit p1.trials.csv --out model.json").exit_code, 2);  // no --study
  const test::CommandRun help = vimg("study fit --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--actuator"), std::string::npos) << help.out;
  expect_model_unchanged();
}

TEST_F(FitCommand, CompareRefusesAMalformedOrNewerModelAndWritesNothing) {
  write("bad.json", "{\n  \"format\": \"vimg-perception-model\",\n  \"version\": 1,\n  \"constants\": {\"lapse_rate\": 2}\n}\n");
  const test::CommandRun bad = vimg("compare a.vimg b.vimg --model bad.json --out c.json");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.out.find("bad.json:4: error: "), std::string::npos) << bad.out;
  write("newer.json",
        "{\n  \"format\": \"vimg-perception-model\",\n  \"version\": 7,\n  \"constants\": {\"temperature_jnd\": 1}\n}\n");
  const test::CommandRun newer = vimg("compare a.vimg b.vimg --model newer.json --out c.json");
  EXPECT_EQ(newer.exit_code, 1);
  EXPECT_NE(newer.out.find("newer.json:3: error: the model is of version 7, a newer version than this vimg reads (1)"),
            std::string::npos)
      << newer.out;
  const test::CommandRun missing = vimg("compare a.vimg b.vimg --model absent.json --out c.json");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.out.find("absent.json: error: "), std::string::npos) << missing.out;
  EXPECT_FALSE(fs::exists(dir_ / "c.json"));
}

TEST_F(FitCommand, CompareUsesTheModelsConstants) {
  // A lapse rate of 0.6 guesses 60 % of the answers among 3 images: every cell at least 0.2, and
  // no weight at all leaves nothing but the lapse and even odds: every cell 1 / 3.
  write("guess.json", "{\"format\": \"vimg-perception-model\", \"version\": 1, \"constants\": {\"temperature_jnd\": 1, "
                      "\"lapse_rate\": 0.6, \"cue_weight\": {\"level\": 0, \"pitch\": 0, \"envelope\": 0}}}\n");
  const test::CommandRun r = vimg("compare a.vimg b.vimg c.vimg --model guess.json --out c.csv");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string csv = read_text(dir_ / "c.csv");
  std::size_t rows = 0;
  for (std::size_t at = csv.find('\n') + 1; at < csv.size(); at = csv.find('\n', at) + 1) {
    const std::size_t end = csv.find('\n', at);
    const std::string line = csv.substr(at, end - at);
    EXPECT_NEAR(std::stod(line.substr(line.rfind(',') + 1)), 1.0 / 3.0, 1e-9) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 9u);
}

}  // namespace
}  // namespace vimg::fit_test
