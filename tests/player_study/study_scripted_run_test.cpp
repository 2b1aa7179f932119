// The scripted matching test as a process (docs/player.md, "Matching test"): every trial of the
// plan recorded once with the scripted choice, a finished participant refused, --restart keeping
// the old file aside, bad responses and a missing masking-noise device refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <string>

#include "tests/player_study/study_process.hpp"

namespace vimg::study_test {
namespace {

using PlayerStudy = PlayerStudyTest;

// Little-endian fields of a RIFF file.
std::uint32_t le16(const std::string& bytes, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes.at(at))) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(bytes.at(at + 1))) << 8;
}
std::uint32_t le32(const std::string& bytes, std::size_t at) { return le16(bytes, at) | le16(bytes, at + 2) << 16; }

TEST_F(PlayerStudy, AScriptedRunOfTwoSetsOfFourImagesRecordsThePlanAndTheResponses) {
  // The shipped example: 2 sets x 4 images x 5 repetitions.
  const fs::path study_file = kExample / "study.xml";
  const MatchingStudy study = load_study(study_file);
  ASSERT_EQ(study.sets.size(), 2u);
  const auto plan = study::plan_matching_trials(study, "P01");
  ASSERT_EQ(plan.size(), 40u);
  const auto chosen = write_responses(root_ / "R.csv", study, plan);
  write_gesture(root_ / "G.csv", 0.1);

  const Finished r = run_player(scripted(study_file, "P01", "out.wav"), root_ / "run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto table = read_matching_trials(root_ / "results" / "P01.trials.csv");
  ASSERT_TRUE(table.ok());
  ASSERT_EQ(table.rows.size(), 40u);
  for (std::size_t k = 1; k <= 40; ++k) {
    const MatchingTrial& row = table.rows[k - 1];
    const auto& set = study.sets[plan[k - 1].set];
    EXPECT_EQ(row.participant, "P01");
    EXPECT_EQ(row.trial, static_cast<int>(k));
    EXPECT_EQ(row.set, set.name);
    EXPECT_EQ(row.presented, study_image_name(set.images[plan[k - 1].image])) << "trial " << k;
    EXPECT_EQ(row.chosen, chosen[k - 1]) << "trial " << k;
    EXPECT_EQ(row.correct, row.presented == row.chosen);
    EXPECT_NEAR(row.rub_s, 0.1, 1e-9);  // the gesture's duration
    EXPECT_NEAR(row.path_mm, kGestureLengthMm, 1e-6);
    EXPECT_EQ(row.response_s, 0.0);
    EXPECT_EQ(row.time_utc.size(), 20u);
    // One status line per trial, once its row is on disk.
    EXPECT_NE(r.out.find("vimg-player: trial " + std::to_string(k) + " of 40 (set " + set.name + "): presented " +
                         row.presented + ", chosen " + row.chosen + "\n"),
              std::string::npos)
        << r.out;
  }
  EXPECT_NE(r.out.find("vimg-player: all 40 trials done"), std::string::npos) << r.out;
  // The output received every trial's rubbing: a complete WAV (RIFF/WAVE as Microsoft's
  // multimedia specification defines it: chunks of a four-letter id, a little-endian length and the
  // data), 32-bit float mono at 8 kHz, each trial's 0.1 s gesture plus a ring-down of at most 0.25 s
  // (docs/player.md) in blocks of 64 samples, every sample finite and within full scale, and the
  // rubbing felt in it, not silence.
  const std::string wav = read_text(root_ / "out.wav");
  ASSERT_GE(wav.size(), 12u);
  ASSERT_EQ(wav.substr(0, 4), "RIFF");
  ASSERT_EQ(wav.substr(8, 4), "WAVE");
  EXPECT_EQ(le32(wav, 4), wav.size() - 8);
  std::map<std::string, std::string> chunks;
  for (std::size_t at = 12; at + 8 <= wav.size();) {
    const std::size_t size = le32(wav, at + 4);
    ASSERT_LE(at + 8 + size, wav.size()) << "chunk '" << wav.substr(at, 4) << "' runs past the end";
    chunks[wav.substr(at, 4)] = wav.substr(at + 8, size);
    at += 8 + size + (size & 1);
  }
  ASSERT_TRUE(chunks.count("fmt ") && chunks.count("data"));
  const std::string& fmt = chunks["fmt "];
  ASSERT_GE(fmt.size(), 16u);
  EXPECT_EQ(le16(fmt, 0), 3u);      // WAVE_FORMAT_IEEE_FLOAT
  EXPECT_EQ(le16(fmt, 2), 1u);      // mono
  EXPECT_EQ(le32(fmt, 4), 8000u);   // samples per second
  EXPECT_EQ(le16(fmt, 14), 32u);    // bits per sample
  const std::string& data = chunks["data"];
  ASSERT_EQ(data.size() % 4, 0u);
  const std::size_t frames = data.size() / 4;
  if (chunks.count("fact")) {
    EXPECT_EQ(le32(chunks["fact"], 0), frames);
  }
  EXPECT_GE(frames, 40u * 800u);                   // 40 gestures of 0.1 s
  EXPECT_LE(frames, 40u * (800u + 2000u + 64u));   // each with at most 0.25 s of ring-down, block-rounded
  double sum_squares = 0.0;
  std::size_t nonzero = 0;
  for (std::size_t n = 0; n < frames; ++n) {
    const std::uint32_t bits = le32(data, 4 * n);
    float v = 0.0f;
    std::memcpy(&v, &bits, sizeof v);
    ASSERT_TRUE(std::isfinite(v) && std::abs(v) <= 1.0f) << "sample " << n << ": " << v;
    sum_squares += static_cast<double>(v) * v;
    nonzero += v != 0.0f;
  }
  EXPECT_GT(std::sqrt(sum_squares / static_cast<double>(frames)), 0.01) << "the rubbing is not in the output";
  EXPECT_GT(nonzero, frames / 10) << "the rubbing is not in the output";
}

TEST_F(PlayerStudy, AFinishedParticipantIsRefusedAndRestartKeepsTheOldFileAside) {
  const fs::path study_file = write_study(root_ / "study", 2, 2, 1);
  const MatchingStudy study = load_study(study_file);
  write_responses(root_ / "R.csv", study, study::plan_matching_trials(study, "P02"));
  write_gesture(root_ / "G.csv", 0.05);
  const fs::path trials = root_ / "results" / "P02.trials.csv";

  ASSERT_EQ(run_player(scripted(study_file, "P02", "a.wav"), root_ / "first").exit_code, 0);
  const std::string finished = read_text(trials);
  ASSERT_EQ(rows_in(trials), 4u);

  const Finished again = run_player(scripted(study_file, "P02", "b.wav"), root_ / "again");
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_NE(again.err.find("participant P02 has finished all 4 trials"), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("--restart"), std::string::npos) << again.err;
  EXPECT_EQ(read_text(trials), finished);
  EXPECT_FALSE(fs::exists(root_ / "b.wav"));  // refused before the output is opened

  auto restart_args = scripted(study_file, "P02", "c.wav");
  restart_args.push_back("--restart");
  const Finished restarted = run_player(restart_args, root_ / "restart");
  ASSERT_EQ(restarted.exit_code, 0) << restarted.err;
  EXPECT_EQ(rows_in(trials), 4u);
  std::vector<fs::path> kept;
  for (const auto& entry : fs::directory_iterator(root_ / "results")) {
    if (entry.path() != trials) kept.push_back(entry.path());
  }
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].filename().string().rfind("P02.trials.", 0), 0u) << kept[0];
  EXPECT_EQ(read_text(kept[0]), finished);  // kept aside, never overwritten
}

TEST_F(PlayerStudy, ResponsesMustAnswerEveryTrialWithAnImageOfItsSet) {
  const fs::path study_file = write_study(root_ / "study", 1, 2, 2);
  write_gesture(root_ / "G.csv", 0.05);
  std::ofstream(root_ / "R.csv") << "trial,chosen\n1,dot\n2,square\n3,line\n";
  const Finished r = run_player(scripted(study_file, "P03", "out.wav"), root_ / "run");
  EXPECT_EQ(r.exit_code, 1);
  const std::string responses = (root_ / "R.csv").string();
  EXPECT_NE(r.err.find(responses + ":3: error: trial 2: 'square' is not an image of its set (dot, line)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(root_ / "results" / "P03.trials.csv"));
  std::ofstream(root_ / "R.csv") << "trial,chosen\n1,dot\n2,line\n";
  const Finished missing = run_player(scripted(study_file, "P03", "out.wav"), root_ / "missing");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find(responses + ": error: no response for trial 3, 4"), std::string::npos) << missing.err;
}

TEST_F(PlayerStudy, MaskingNoiseNeedsAnAudioOutputThatExistsAndIsNotTheActuators) {
  write_gesture(root_ / "G.csv", 0.05);
  const fs::path absent = write_study(root_ / "absent", 1, 2, 1, "  <maskingNoise device=\"No Such Card\" level=\"0.2\"/>\n");
  write_responses(root_ / "R.csv", load_study(absent), study::plan_matching_trials(load_study(absent), "P04"));
  const Finished r = run_player(scripted(absent, "P04", "out.wav"), root_ / "absent_run");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("masking noise device 'No Such Card' does not exist; the audio outputs are (SDL driver dummy): "
                       "'System audio output device'"),
            std::string::npos)
      << r.err;
  // SDL's dummy driver has one output: the noise plays there while the actuator's drive goes to a file.
  const fs::path present =
      write_study(root_ / "present", 1, 2, 1, "  <maskingNoise device=\"System audio output device\" level=\"0.2\"/>\n");
  const Finished ok = run_player(scripted(present, "P04", "out.wav"), root_ / "present_run");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("masking noise white noise, RMS 0.2, on 'System audio output device'"), std::string::npos) << ok.out;
  EXPECT_EQ(rows_in(root_ / "results" / "P04.trials.csv"), 2u);
  // The actuator's own audio output cannot mask it.
  auto same = study_args(present, "P05",
                         {"--responses", (root_ / "R.csv").string(), "--gesture", (root_ / "G.csv").string(), "--output",
                          "audio:System audio output device"});
  const Finished refused = run_player(same, root_ / "same_run");
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("is the actuator's output"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace vimg::study_test
