#include "apps/vimg-player/player_args.hpp"

#include <gtest/gtest.h>

namespace vimg::player_app {
namespace {

struct Parsed {
  ArgsResult result;
  std::string err;
};

Parsed parse(std::vector<std::string> arguments) {
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  Parsed p{parse_player_args(arguments), ""};
  testing::internal::GetCapturedStdout();
  p.err = testing::internal::GetCapturedStderr();
  return p;
}

TEST(PlayerArgs, DefaultsAreAudioAt8kHzWithRealtimePriority) {
  const Parsed r = parse({"image.vimg"});
  ASSERT_TRUE(r.result.args.has_value()) << r.err;
  EXPECT_EQ(r.result.args->image_path, "image.vimg");
  EXPECT_EQ(r.result.args->output, "audio");
  EXPECT_EQ(r.result.args->rate_hz, 8000.0);
  EXPECT_EQ(r.result.args->realtime_priority, 80);
  EXPECT_FALSE(r.result.args->px_per_mm.has_value());
  EXPECT_FALSE(r.result.args->window_size.has_value());
}

TEST(PlayerArgs, RealtimePriorityTakesZeroToNinetyNine) {
  EXPECT_EQ(parse({"i.vimg", "--realtime-priority", "0"}).result.args->realtime_priority, 0);
  EXPECT_EQ(parse({"i.vimg", "--realtime-priority", "99"}).result.args->realtime_priority, 99);
  for (const char* bad : {"100", "-1", "8x", "", "1.5"}) {
    const Parsed r = parse({"i.vimg", "--realtime-priority", bad});
    EXPECT_FALSE(r.result.args.has_value()) << bad;
    EXPECT_EQ(r.result.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("vimg-player: error: --realtime-priority"), std::string::npos) << r.err;
  }
  EXPECT_EQ(parse({"i.vimg", "--realtime-priority"}).result.exit_code, 2);
}

TEST(PlayerArgs, BadValuesAreUsageErrorsThatSayWhatIsWrong) {
  for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
           {"i.vimg", "--rate", "0"}, {"i.vimg", "--rate", "nan"}, {"i.vimg", "--px-per-mm", "-3"},
           {"i.vimg", "--window", "10x10"}, {"i.vimg", "--frobnicate"}, {"a.vimg", "b.vimg"}, {}}) {
    const Parsed r = parse(bad);
    EXPECT_FALSE(r.result.args.has_value());
    EXPECT_EQ(r.result.exit_code, 2);
    EXPECT_EQ(r.err.rfind("vimg-player: error: ", 0), 0u) << r.err;
  }
  EXPECT_NE(parse({"i.vimg", "--window", "10x10"}).err.find("'10x10' is not WIDTHxHEIGHT of at least 64x64"), std::string::npos);
  EXPECT_NE(parse({}).err.find("IMAGE is required"), std::string::npos);
}

TEST(PlayerArgs, GoodValuesArrive) {
  const Parsed r = parse({"i.vimg", "--window", "800x600", "--px-per-mm", "4.5", "--output", "wav:x.wav", "--actuator", "p.xml"});
  ASSERT_TRUE(r.result.args.has_value()) << r.err;
  EXPECT_EQ(r.result.args->window_size, (std::pair{800, 600}));
  EXPECT_EQ(r.result.args->px_per_mm, 4.5);
  EXPECT_EQ(r.result.args->output, "wav:x.wav");
  EXPECT_EQ(r.result.args->actuator_path, "p.xml");
  EXPECT_TRUE(parse({"--calibrate"}).result.args.has_value());
}

TEST(PlayerArgs, HelpAndVersionExitZero) {
  EXPECT_FALSE(parse({"--help"}).result.args.has_value());
  EXPECT_EQ(parse({"--help"}).result.exit_code, 0);
  EXPECT_EQ(parse({"--version"}).result.exit_code, 0);
}

TEST(PlayerArgs, EqualizeIsOffUnlessAskedFor) {
  EXPECT_FALSE(parse({"i.vimg", "--actuator", "lra.xml"}).result.args->equalize);
  const Parsed r = parse({"i.vimg", "--actuator", "lra.xml", "--equalize"});
  ASSERT_TRUE(r.result.args.has_value()) << r.err;
  EXPECT_TRUE(r.result.args->equalize);
  EXPECT_EQ(r.result.args->actuator_path, "lra.xml");
  const Parsed bad = parse({"i.vimg", "--equalize=maybe"});
  EXPECT_FALSE(bad.result.args.has_value());
  EXPECT_EQ(bad.result.exit_code, 2);
}

}  // namespace
}  // namespace vimg::player_app

namespace vimg::player_app {
namespace {

TEST(PlayerArgs, StudyOptionsArriveTogether) {
  const Parsed r = parse({"--study", "s.xml", "--participant", "P-01_a", "--results", "out", "--restart"});
  ASSERT_TRUE(r.result.args.has_value()) << r.err;
  EXPECT_EQ(r.result.args->study_path, "s.xml");
  EXPECT_EQ(r.result.args->participant, "P-01_a");
  EXPECT_EQ(r.result.args->results_dir, "out");
  EXPECT_TRUE(r.result.args->restart);
  EXPECT_FALSE(r.result.args->responses_path.has_value());
  const Parsed scripted = parse({"--study", "s.xml", "--participant", "P", "--results", "out", "--responses", "r.csv",
                                 "--gesture", "g.csv", "--output", "wav:x.wav"});
  ASSERT_TRUE(scripted.result.args.has_value()) << scripted.err;
  EXPECT_EQ(scripted.result.args->responses_path, "r.csv");
  EXPECT_EQ(scripted.result.args->gesture_path, "g.csv");
  EXPECT_FALSE(parse({"i.vimg"}).result.args->study_path.has_value());
}

TEST(PlayerArgs, StudyOptionsThatDoNotFitAreUsageErrors) {
  for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
           {"--study", "s.xml"},
           {"--study", "s.xml", "--participant", "P"},
           {"--study", "s.xml", "--results", "out"},
           {"--participant", "P", "--results", "out", "i.vimg"},
           {"i.vimg", "--restart"},
           {"--study", "s.xml", "--participant", "P", "--results", "out", "--responses", "r.csv"},
           {"--study", "s.xml", "--participant", "P", "--results", "out", "--gesture", "g.csv"},
           {"--study", "s.xml", "--participant", "P", "--results", "out", "i.vimg"},
           {"--study", "s.xml", "--participant", "P", "--results", "out", "--calibrate"},
           {"--study", "", "--participant", "P", "--results", "out"},
           {"--study", "s.xml", "--participant", "a b", "--results", "out"},
           {"--study", "s.xml", "--participant", "../x", "--results", "out"},
           {"--study", "s.xml", "--participant", std::string(65, 'p'), "--results", "out"}}) {
    const Parsed r = parse(bad);
    EXPECT_FALSE(r.result.args.has_value()) << bad[0];
    EXPECT_EQ(r.result.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("vimg-player: error: ", 0), 0u) << r.err;
  }
  EXPECT_NE(parse({"--study", "s.xml", "--participant", "a/b", "--results", "o"}).err.find("--participant 'a/b': an ID is"),
            std::string::npos);
  EXPECT_NE(parse({"--study", "s.xml"}).err.find("--study needs --participant and --results"), std::string::npos);
}

}  // namespace
}  // namespace vimg::player_app
