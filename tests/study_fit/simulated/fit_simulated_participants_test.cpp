// `vimg study fit` on simulated participants through the real pipeline: each participant's choices
// are drawn from a known discrimination model (tests/study_fit/fit_simulation.hpp) over the cue
// distances of the study's images as `vimg compare` renders them, played as scripted responses by
// vimg-player --study headless (SDL's dummy drivers, several participants at once), and fitted by
// vimg study fit as a researcher runs it. The fit recovers the known constants within its stated
// intervals; participants who confuse one pair 40 % of the time yield a model that predicts that
// pair within 0.15 through vimg compare --model, and vimg study report --predicted sets it beside
// the measured confusion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "storage/study/perception_model_file.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/trial_table.hpp"
#include "study/compare.hpp"
#include "study/trial_plan.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/export/json_reader.hpp"
#include "tests/study_fit/fit_files.hpp"
#include "tests/study_fit/fit_simulation.hpp"

namespace vimg::fit_test {
namespace {

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";
const std::string kPlayer = VIMG_BINARY_DIR "/apps/vimg-player/vimg-player";
constexpr double kCanvasMm = 40.0;

// Near-duplicates a and b (a 5 % longer period), c an octave lower in pitch, d 7 dB weaker.
const std::vector<Surface> kTextures{{"a", 2.0, 0.7}, {"b", 2.1, 0.7}, {"c", 4.0, 0.7}, {"d", 2.0, 0.3}};

class SimulatedParticipants : public FitFolderTest {
 protected:
  void SetUp() override {
    FitFolderTest::SetUp();
    study_file_ = write_surface_study(dir_, "textures", kTextures, repetitions_, kCanvasMm);
    auto loaded = load_matching_study(study_file_);
    ASSERT_TRUE(loaded.study) << (loaded.diagnostics.empty() ? "" : loaded.diagnostics[0].to_string());
    study_ = *loaded.study;
    // One short stroke inside the canvas per trial: the player's timing does not enter the fit.
    std::ofstream(dir_ / "G.csv") << "time_s,finger,x_mm,y_mm,pressure,phase\n0,0,5,20,1,down\n0.01,0,15,20,1,move\n"
                                     "0.02,0,25,20,1,up\n";
    fs::create_directories(dir_ / "results");
  }

  // The cue distances of the set as vimg compare (and so vimg study fit) renders the images.
  CueMatrix rendered_cues() const {
    study::CompareRequest request;
    request.inputs = study_.sets[0].images;
    const study::CompareResult r = study::run_compare(request);
    EXPECT_TRUE(r.ok());
    return r.cues;
  }

  // Writes R_<participant>.csv choosing, for trial k, choose(presented image, k).
  template <class Choose>
  void write_responses(const std::string& participant, Choose&& choose) const {
    const auto plan = study::plan_matching_trials(study_, participant);
    std::ofstream out(dir_ / ("R_" + participant + ".csv"));
    out << "trial,chosen\n";
    for (std::size_t k = 0; k < plan.size(); ++k) out << k + 1 << "," << kTextures[choose(plan[k].image, k)].stem << "\n";
  }

  // vimg-player --study for every participant at once (each waits on its real-time output), then
  // a check that every one recorded all its trials.
  void play(const std::vector<std::string>& participants) const {
    std::string script = "cd '" + dir_.string() + "' || exit 1; export SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy; ";
    for (const std::string& p : participants) {
      script += "(timeout 120 '" + kPlayer + "' --study study.xml --participant " + p +
                " --results results --window 800x600 --px-per-mm 3 --responses R_" + p +
                ".csv --gesture G.csv --output wav:" + p + ".wav > " + p + ".log 2>&1; echo $? > " + p + ".rc) & ";
    }
    script += "wait";
    test::run_command(script);
    const std::size_t trials = study_.sets[0].images.size() * static_cast<std::size_t>(repetitions_);
    for (const std::string& p : participants) {
      ASSERT_EQ(read_text(dir_ / (p + ".rc")), "0\n") << read_text(dir_ / (p + ".log"));
      const auto table = read_matching_trials(dir_ / "results" / (p + ".trials.csv"));
      ASSERT_TRUE(table.ok());
      ASSERT_EQ(table.rows.size(), trials) << p;
    }
  }

  test::CommandRun fit(const std::string& out) const {
    return test::run_command("cd '" + dir_.string() + "' && timeout 120 '" + kVimg +
                             "' study fit results/*.trials.csv --study study.xml --out " + out);
  }

  int repetitions_ = 30;
  fs::path study_file_;
  MatchingStudy study_;
};

TEST_F(SimulatedParticipants, TheFitRecoversTheKnownConstantsWithinItsIntervals) {
  const CueMatrix cues = rendered_cues();
  ASSERT_EQ(cues.size(), 4u);
  DiscriminationConstants truth;
  truth.lapse_rate = 0.08;
  truth.cue_weight = {1.0, 4.0, 0.6};  // a and b 2 pitch JNDs apart (0.5 by default), the rest far: the lapse shows
  const std::vector<std::string> participants{"S1", "S2", "S3", "S4"};
  SplitMix random(20261127);
  for (const std::string& p : participants) {
    write_responses(p, [&](std::size_t presented, std::size_t) { return draw(choice_row(cues, presented, truth), random); });
  }
  play(participants);

  const test::CommandRun r = fit("model.json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::cout << r.out;  // the fitted constants against the truth, in the test's log
  const PerceptionModelLoadResult model = load_perception_model(dir_ / "model.json");
  ASSERT_TRUE(model.model) << r.out;
  const test::Json j = test::JsonReader::parse(read_text(dir_ / "model.json"));
  const DiscriminationConstants defaults;
  std::vector<std::string> fitted;
  for (const test::Json& name : j["fitted"].array()) fitted.push_back(name.string());
  ASSERT_FALSE(fitted.empty()) << r.out;
  EXPECT_EQ(fitted.front(), "lapse_rate") << r.out;
  for (std::size_t k = 0; k <= kCueCount; ++k) {
    const std::string name = k == 0 ? "lapse_rate" : "cue_weight." + std::string(cue_name(k - 1));
    const double true_value = k == 0 ? truth.lapse_rate : truth.cue_weight[k - 1];
    const double value = k == 0 ? model.model->constants.lapse_rate : model.model->constants.cue_weight[k - 1];
    if (std::find(fitted.begin(), fitted.end(), name) == fitted.end()) {
      // Not identified: its default, and a warning naming it on stderr and in the file.
      EXPECT_EQ(value, k == 0 ? defaults.lapse_rate : defaults.cue_weight[k - 1]) << name;
      EXPECT_NE(r.out.find("vimg study fit: warning: " + name + ":"), std::string::npos) << r.out;
      continue;
    }
    const auto& bounds = j["intervals"]["bounds"][name].array();
    EXPECT_LE(bounds[0].number(), true_value) << name << "\n" << r.out;
    EXPECT_GE(bounds[1].number(), true_value) << name << "\n" << r.out;
    EXPECT_LE(bounds[0].number(), value) << name;
    EXPECT_GE(bounds[1].number(), value) << name;
  }
  // The textures differ in every cue, so some weight is identified besides the lapse rate...
  EXPECT_GE(fitted.size(), 2u) << r.out;
  // ... and the trials tell the lapse rate from its default 0 (the truth is 0.08).
  EXPECT_GT(j["intervals"]["bounds"]["lapse_rate"].array()[0].number(), 0.0) << r.out;
  // Held out, the fitted constants predict the participants better than the defaults (far from the
  // truth) and than the baseline (the defaults with a fitted lapse rate), over all of them: one
  // participant of four may go the other way by chance.
  const auto& held_out = j["leave_one_participant_out"];
  ASSERT_EQ(held_out["participants"].array().size(), 4u);
  EXPECT_GT(held_out["total"]["fitted"].number(), held_out["total"]["default"].number()) << r.out;
  EXPECT_GT(held_out["total"]["fitted"].number(), held_out["total"]["baseline"].number()) << r.out;
  EXPECT_EQ(held_out["total"]["trials"].number(), 4.0 * 4 * repetitions_);
  EXPECT_NE(r.out.find("Leave one participant out"), std::string::npos) << r.out;
  EXPECT_EQ(j["fitted_on"]["participants"].number(), 4.0);
}

TEST_F(SimulatedParticipants, OnePairConfused40PercentOfTheTimeIsPredictedWithin0Point15) {
  // b 4 dB weaker than a (two level JNDs), c at a third of its frequency, d 17 dB weaker:
  // the default constants predict a and b told apart far more often than these participants do
  // (about 17 % confused), and every other pair far apart.
  for (const Surface& s : {Surface{"b", 2.0, 0.44}, Surface{"c", 6.0, 0.7}, Surface{"d", 2.0, 0.1}})
    write_surface_image(dir_, s, kCanvasMm);
  // Every participant takes b for a (and a for b) on 2 of every 5 presentations, and is right otherwise.
  const std::vector<std::string> participants{"C1", "C2", "C3"};
  for (const std::string& p : participants) {
    std::vector<int> seen(4, 0);
    write_responses(p, [&](std::size_t presented, std::size_t) -> std::size_t {
      const int n = seen[presented]++;
      if (presented <= 1 && n % 5 < 2) return 1 - presented;
      return presented;
    });
  }
  play(participants);
  const test::CommandRun r = fit("model.json");
  ASSERT_EQ(r.exit_code, 0) << r.out;

  const auto compare = [&](const std::string& model, const std::string& out) {
    const test::CommandRun run = test::run_command("cd '" + dir_.string() + "' && timeout 120 '" + kVimg +
                                                   "' compare a.vimg b.vimg c.vimg d.vimg " + model + " --out " + out);
    EXPECT_EQ(run.exit_code, 0) << run.out;
    return test::JsonReader::parse(read_text(dir_ / out));
  };
  const test::Json defaults = compare("", "defaults.json");
  const test::Json c = compare("--model model.json", "c.json");
  const auto& p = c["predicted_confusion"].array();
  std::cout << "a -> b predicted " << p[0].array()[1].number() << " (default constants "
            << defaults["predicted_confusion"].array()[0].array()[1].number() << "), measured 0.4\n";
  // Predicted about 0.26, not 0.40, and not by a bias of the fit or its lapse rate: d differs from a
  // and b along the same cues, 8.4 and 6.4 JNDs where a and b differ by 2, so no constants predict
  // a -> b above 0.37, and there d would be taken for a or b 40 % of the time where these
  // participants never did. The maximum of the likelihood keeps d apart and a -> b at 0.27
  // (FitMisspecified.APairConfused40PercentBesideOnesNeverConfusedOnTheSameCuesIsFittedNearerToAQuarter).
  EXPECT_NEAR(p[0].array()[1].number(), 0.4, 0.15) << r.out;
  EXPECT_NEAR(p[1].array()[0].number(), 0.4, 0.15) << r.out;
  // The fit did it: the default constants miss the pair by more.
  EXPECT_GT(std::abs(defaults["predicted_confusion"].array()[0].array()[1].number() - 0.4), 0.15);
  // The other pairs were never confused: the model keeps them apart.
  EXPECT_LT(p[2].array()[0].number() + p[2].array()[1].number() + p[2].array()[3].number(), 0.15) << r.out;

  // The report sets predicted and measured side by side, and names the model the prediction used.
  const test::CommandRun report = test::run_command("cd '" + dir_.string() + "' && timeout 60 '" + kVimg +
                                                    "' study report results/*.trials.csv --predicted c.json --out r.md");
  ASSERT_EQ(report.exit_code, 0) << report.out;
  const std::string md = read_text(dir_ / "r.md");
  EXPECT_NE(md.find("Prediction from c.json, made with the model model.json (temperature 0.91 JND, lapse rate "),
            std::string::npos)
      << md;
  EXPECT_NE(md.find(" / 0.40"), std::string::npos) << md;  // measured a -> b, beside its prediction
}

}  // namespace
}  // namespace vimg::fit_test
