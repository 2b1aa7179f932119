// The seeded trial order (study/trial_plan.hpp) against an independent reference: the Python
// script beside this file implements the header's definition in Python integers, checks that it
// gives the values trial_plan_test.cpp pins (--check), and prints ~120 cases ("CASE: VALUE"):
// shuffles, participant seeds, matching plans and location plans with their data seeds. Every
// case is computed here with the C++ code and must print the same VALUE.
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "study/trial_plan.hpp"
#include "tests/cli/run_command.hpp"

namespace vimg::study {
namespace {

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::uint64_t u64(const std::string& text) { return std::stoull(text); }

std::string hex16(std::uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIX64, v);
  return text;
}

// The VALUE the C++ code gives for a CASE of the reference's output; empty for a case it does not know.
std::string evaluate(const std::vector<std::string>& c) {
  std::ostringstream out;
  if (c.size() == 3 && c[0] == "shuffle") {
    const auto order = shuffled_indices(std::stoul(c[1]), u64(c[2]));
    for (std::size_t i = 0; i < order.size(); ++i) out << (i ? " " : "") << order[i];
    return out.str();
  }
  if (c.size() == 3 && c[0] == "participant_seed") return std::to_string(participant_seed(u64(c[1]), c[2]));
  if (c.size() == 5 && c[0] == "matching") {
    MatchingStudy s;
    s.seed = u64(c[1]);
    s.repetitions = std::stoi(c[2]);
    std::istringstream sizes(c[3]);
    for (std::string size; std::getline(sizes, size, ',');) {
      StudyImageSet set;
      set.name = "set" + std::to_string(s.sets.size());
      for (int i = 0; i < std::stoi(size); ++i) set.images.push_back("image" + std::to_string(i) + ".vimg");
      s.sets.push_back(set);
    }
    const auto plan = plan_matching_trials(s, c[4]);
    for (std::size_t k = 0; k < plan.size(); ++k) out << (k ? " " : "") << plan[k].set << ":" << plan[k].image;
    return out.str();
  }
  if (c.size() == 5 && c[0] == "location") {
    LocationStudy s;
    s.order = c[1] == "blocked" ? TrialOrder::blocked : TrialOrder::interleaved;
    s.seed = u64(c[2]);
    s.trials_per_metaphor = std::stoi(c[3]);
    const auto plan = plan_location_trials(s, c[4]);
    for (std::size_t k = 0; k < plan.size(); ++k) {
      out << (k ? " " : "") << (plan[k].metaphor == LocationMetaphor::roughness ? 'R' : 'T') << ":" << hex16(plan[k].data_seed);
    }
    return out.str();
  }
  return {};
}

TEST(TrialPlan, EqualsThePythonReferenceOfTheDefinition) {
  const test::CommandRun run =
      test::run_command("/usr/bin/python3 '" VIMG_SOURCE_DIR "/tests/study_core/trial_plan_reference.py' --check");
  ASSERT_EQ(run.exit_code, 0) << "the reference disagrees with the pinned values:\n" << run.out;
  std::istringstream lines(run.out);
  int compared = 0;
  for (std::string line; std::getline(lines, line);) {
    const std::size_t colon = line.find(": ");
    ASSERT_NE(colon, std::string::npos) << line;
    const std::vector<std::string> c = words(line.substr(0, colon));
    const std::string value = line.substr(colon + 2);
    const std::string ours = evaluate(c);
    ASSERT_FALSE(ours.empty() && !value.empty()) << "a case this test does not know: " << line;
    EXPECT_EQ(ours, value) << line.substr(0, colon);
    ++compared;
  }
  EXPECT_GE(compared, 120) << run.out;
}

}  // namespace
}  // namespace vimg::study
