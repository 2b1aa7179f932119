#include "apps/vimg-player/player_args.hpp"

#include <gtest/gtest.h>

namespace vimg::player_app {
namespace {

ArgsResult parse(std::vector<std::string> arguments) { return parse_player_args(arguments); }

TEST(PlayerArgs, DefaultsAreAudioAt8kHzWithRealtimePriority) {
  const ArgsResult r = parse({"image.vimg"});
  ASSERT_TRUE(r.args.has_value()) << r.error;
  EXPECT_EQ(r.args->image_path, "image.vimg");
  EXPECT_EQ(r.args->output, "audio");
  EXPECT_EQ(r.args->rate_hz, 8000.0);
  EXPECT_EQ(r.args->realtime_priority, 80);
}

TEST(PlayerArgs, RealtimePriorityTakesZeroToNinetyNine) {
  EXPECT_EQ(parse({"i.vimg", "--realtime-priority", "0"}).args->realtime_priority, 0);
  EXPECT_EQ(parse({"i.vimg", "--realtime-priority", "99"}).args->realtime_priority, 99);
  for (const char* bad : {"100", "-1", "8x", "", "1.5"}) {
    const ArgsResult r = parse({"i.vimg", "--realtime-priority", bad});
    EXPECT_FALSE(r.args.has_value()) << bad;
    EXPECT_EQ(r.error, "--realtime-priority needs a whole number in 0..99") << bad;
  }
  EXPECT_FALSE(parse({"i.vimg", "--realtime-priority"}).args.has_value());
}

TEST(PlayerArgs, BadValuesSayWhatIsWrong) {
  EXPECT_EQ(parse({"i.vimg", "--rate", "0"}).error, "--rate needs a number of Hz in 1..48000");
  EXPECT_EQ(parse({"i.vimg", "--px-per-mm", "-3"}).error, "--px-per-mm needs a number above 0");
  EXPECT_EQ(parse({"i.vimg", "--window", "10x10"}).error, "--window needs WIDTHxHEIGHT, e.g. 800x600");
  EXPECT_EQ(parse({"i.vimg", "--frobnicate"}).error, "unknown option --frobnicate");
  EXPECT_EQ(parse({"a.vimg", "b.vimg"}).error, "only one IMAGE, not also b.vimg");
  EXPECT_EQ(parse({}).error, "needs an IMAGE");
}

TEST(PlayerArgs, HelpGivesNoArgsAndNoError) {
  const ArgsResult r = parse({"--help"});
  EXPECT_FALSE(r.args.has_value());
  EXPECT_TRUE(r.error.empty());
}

}  // namespace
}  // namespace vimg::player_app
