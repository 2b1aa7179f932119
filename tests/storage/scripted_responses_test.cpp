// Scripted responses of a matching test (storage/study/scripted_responses.hpp).
#include "storage/study/scripted_responses.hpp"

#include <gtest/gtest.h>

namespace vimg {
namespace {

const std::vector<std::vector<std::string>> kStems{{"dot", "line"}, {"a", "b", "c"}};
const std::vector<std::size_t> kPlan{0, 0, 1};  // the set of trials 1, 2 and 3

std::string all_errors(const ResponsesResult& r) {
  std::string text;
  for (const auto& d : r.diagnostics) text += d.to_string() + "\n";
  return text;
}

TEST(StudyResponses, ReadsEveryTrialInAnyOrderByStem) {
  const auto r = parse_responses("trial,chosen\r\n3,c\n1, dot\n\n2,dot\n", "r.csv", kStems, kPlan);
  ASSERT_TRUE(r.ok()) << all_errors(r);
  EXPECT_EQ(*r.chosen, (std::vector<std::size_t>{0, 0, 2}));
}

TEST(StudyResponses, EveryProblemIsNamedAtItsLine) {
  const auto r = parse_responses("trial,chosen\n1,dot\n1,line\n2,square\n9,a\nx,a\n3\n", "r.csv", kStems, kPlan);
  EXPECT_FALSE(r.ok());
  const std::string text = all_errors(r);
  EXPECT_NE(text.find("r.csv:3: error: trial 1 is answered twice (first at line 2)"), std::string::npos) << text;
  EXPECT_NE(text.find("r.csv:4: error: trial 2: 'square' is not an image of its set (dot, line)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("r.csv:5: error: trial '9' is not a trial number of this study (1..3)"), std::string::npos) << text;
  EXPECT_NE(text.find("r.csv:6: error: trial 'x'"), std::string::npos) << text;
  EXPECT_NE(text.find("r.csv:7: error: expected 2 cells"), std::string::npos) << text;
}

TEST(StudyResponses, ATrialWithoutAResponseStopsTheRun) {
  const auto r = parse_responses("trial,chosen\n1,dot\n", "r.csv", kStems, kPlan);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(all_errors(r).find("r.csv: error: no response for trial 2, 3: every trial of the study (1..3) needs one"),
            std::string::npos)
      << all_errors(r);
}

TEST(StudyResponses, TheHeaderComesFirst) {
  EXPECT_NE(all_errors(parse_responses("trial,choice\n1,dot\n", "r.csv", kStems, kPlan))
                .find("r.csv:1: error: the header must be 'trial,chosen'"),
            std::string::npos);
  EXPECT_NE(all_errors(parse_responses("", "r.csv", kStems, kPlan)).find("r.csv: error: empty file"), std::string::npos);
}

TEST(StudyResponses, AFileThatIsNotThereIsNamed) {
  const auto r = load_responses("/nonexistent/responses.csv", kStems, kPlan);
  EXPECT_FALSE(r.ok());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].to_string().rfind("/nonexistent/responses.csv: error: ", 0), 0u);
}

}  // namespace
}  // namespace vimg
