// The matching report reproduces the primitives paper's tables (section 3) from trials crafted to
// hold them: 20 participants, two sets of four images, five repetitions. Every expected number
// below is worked out by hand from the paper's Tables 1-6, not computed by the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "study/report_matching.hpp"
#include "study/report_predicted.hpp"
#include "study/report_tables.hpp"

namespace vimg::study {
namespace {

std::string participant_id(int p) { return std::string(p < 10 ? "p0" : "p") + std::to_string(p); }

// Table 1 (different complexity): s3 once taken for s4 (by p04), s4 once for s3 (by p05).
// Table 2 (same complexity): s2 three times taken for s4 and s4 three times for s2 (p01-p03 once each).
std::vector<MatchingTrial> paper_trials() {
  std::vector<MatchingTrial> trials;
  for (int p = 1; p <= 20; ++p) {
    int number = 0;
    for (const std::string set : {"complexity", "same"}) {
      for (int rep = 0; rep < 5; ++rep) {
        for (int image = 1; image <= 4; ++image) {
          MatchingTrial t;
          t.participant = participant_id(p);
          t.set = set;
          t.trial = ++number;
          t.presented = "s" + std::to_string(image);
          t.chosen = t.presented;
          if (rep == 0 && set == "complexity" && ((p == 4 && image == 3) || (p == 5 && image == 4))) t.chosen = p == 4 ? "s4" : "s3";
          if (rep == 0 && set == "same" && p <= 3 && (image == 2 || image == 4)) t.chosen = image == 2 ? "s4" : "s2";
          t.correct = t.presented == t.chosen;
          trials.push_back(t);
        }
      }
    }
  }
  return trials;
}

using Matrix = std::vector<std::vector<std::size_t>>;

void expect_counts(const ImageCounts& c, std::size_t tp, std::size_t fn, std::size_t fp, std::size_t tn) {
  EXPECT_EQ(c.tp, tp) << c.image;
  EXPECT_EQ(c.fn, fn) << c.image;
  EXPECT_EQ(c.fp, fp) << c.image;
  EXPECT_EQ(c.tn, tn) << c.image;
}

TEST(MatchingReport, ReproducesThePapersTables) {
  const MatchingReport r = make_matching_report(paper_trials());
  ASSERT_EQ(r.sets.size(), 2u);
  const SetReport& a = r.sets[0];
  const SetReport& b = r.sets[1];
  EXPECT_EQ(a.name, "complexity");  // the order in which the trials name them
  EXPECT_EQ(b.name, "same");
  EXPECT_EQ(a.images, (std::vector<std::string>{"s1", "s2", "s3", "s4"}));
  // Tables 1 and 2.
  EXPECT_EQ(a.comparison, (Matrix{{100, 0, 0, 0}, {0, 100, 0, 0}, {0, 0, 99, 1}, {0, 0, 1, 99}}));
  EXPECT_EQ(b.comparison, (Matrix{{100, 0, 0, 0}, {0, 97, 0, 3}, {0, 0, 100, 0}, {0, 3, 0, 97}}));
  // Tables 3-5: each image against the other three, 400 trials per set.
  expect_counts(a.per_image[0], 100, 0, 0, 300);
  expect_counts(a.per_image[2], 99, 1, 1, 299);  // Table 3
  expect_counts(a.per_image[3], 99, 1, 1, 299);
  expect_counts(b.per_image[0], 100, 0, 0, 300);  // Table 4
  expect_counts(b.per_image[2], 100, 0, 0, 300);
  expect_counts(b.per_image[1], 97, 3, 3, 297);  // Table 5
  expect_counts(b.per_image[3], 97, 3, 3, 297);
  EXPECT_DOUBLE_EQ(*a.per_image[2].hit_rate, 0.99);
  EXPECT_DOUBLE_EQ(*a.per_image[2].false_alarm_rate, 1.0 / 300.0);
  EXPECT_DOUBLE_EQ(*b.per_image[1].hit_rate, 0.97);
  EXPECT_DOUBLE_EQ(*b.per_image[1].false_alarm_rate, 0.01);
  // Table 6's means: 0.995 and 0.985 (the paper's 98.5 % for the same-complexity set).
  EXPECT_EQ(a.trials, 400u);
  EXPECT_EQ(a.correct, 398u);
  EXPECT_DOUBLE_EQ(a.accuracy, 0.995);
  EXPECT_EQ(b.correct, 394u);
  EXPECT_DOUBLE_EQ(b.accuracy, 0.985);
  EXPECT_DOUBLE_EQ(a.chance, 0.25);
  // The 95 % Wilson intervals of 398/400 and 394/400, from SciPy 1.10.1's
  // binomtest(k, n).proportion_ci(0.95, method="wilson").
  ASSERT_TRUE(a.accuracy_ci95 && b.accuracy_ci95);
  EXPECT_NEAR(a.accuracy_ci95->lower, 0.9819550815637569, 1e-12);
  EXPECT_NEAR(a.accuracy_ci95->upper, 0.9986277470452897, 1e-12);
  EXPECT_NEAR(b.accuracy_ci95->lower, 0.9676653664151732, 1e-12);
  EXPECT_NEAR(b.accuracy_ci95->upper, 0.9931077080805591, 1e-12);
}

TEST(MatchingReport, PerParticipantAccuracyAndWelchBetweenSets) {
  const MatchingReport r = make_matching_report(paper_trials());
  const SetReport& a = r.sets[0];
  const SetReport& b = r.sets[1];
  ASSERT_EQ(a.participants.size(), 20u);
  EXPECT_EQ(a.participants[3].participant, "p04");
  EXPECT_EQ(a.participants[3].trials, 20u);
  EXPECT_EQ(a.participants[3].correct, 19u);
  EXPECT_DOUBLE_EQ(a.participants[3].accuracy, 0.95);
  EXPECT_DOUBLE_EQ(b.participants[0].accuracy, 0.9);
  EXPECT_DOUBLE_EQ(b.participants[19].accuracy, 1.0);
  ASSERT_EQ(r.set_comparisons.size(), 1u);
  const GroupComparison& c = r.set_comparisons[0];
  // Set a: 18 x 1.0 and 2 x 0.95, sum of squares 0.0045; set b: 17 x 1.0 and 3 x 0.9, 0.0255.
  // t = 0.01 / sqrt(0.03 / 380); df = 19 * 0.03^2 / (0.0045^2 + 0.0255^2) = 171 / 6.705;
  // d = 0.01 / sqrt(0.03 / 38); p from SciPy's ttest_ind(equal_var=False) on the same values.
  ASSERT_TRUE(c.welch && c.cohens_d);
  EXPECT_NEAR(c.summary_a.mean, 0.995, 1e-15);
  EXPECT_NEAR(c.summary_b.mean, 0.985, 1e-15);
  EXPECT_NEAR(c.welch->t, 0.01 / std::sqrt(0.03 / 380.0), 1e-9);
  EXPECT_NEAR(c.welch->df, 171.0 / 6.705, 1e-9);
  EXPECT_NEAR(c.welch->p, 0.27087334988373724, 1e-9);
  EXPECT_NEAR(*c.cohens_d, 0.01 / std::sqrt(0.03 / 38.0), 1e-9);
}

TEST(MatchingReport, ThreeSetsGiveEveryPair) {
  std::vector<MatchingTrial> trials;
  for (const std::string set : {"x", "y", "z"}) {
    for (int p = 0; p < 2; ++p) {
      MatchingTrial t;
      t.participant = "p" + std::to_string(p);
      t.set = set;
      t.presented = "a";
      t.chosen = p == 0 ? "a" : "b";
      trials.push_back(t);
    }
  }
  const MatchingReport r = make_matching_report(trials);
  ASSERT_EQ(r.set_comparisons.size(), 3u);
  EXPECT_EQ(r.set_comparisons[2].a, "y");
  EXPECT_EQ(r.set_comparisons[2].b, "z");
  // An image only chosen, never presented, is in the set with no hit rate.
  EXPECT_EQ(r.sets[0].images, (std::vector<std::string>{"a", "b"}));
  EXPECT_FALSE(r.sets[0].per_image[1].hit_rate);
  EXPECT_EQ(r.sets[0].per_image[1].fp, 1u);
}

TEST(MatchingReport, PredictionRestrictedToTheSetAndCorrelated) {
  MatchingReport r = make_matching_report(paper_trials());
  // A prediction over five images (one not in the set): rows renormalised over s1..s4.
  PredictedConfusion p;
  p.source = "compare.json";
  p.stems = {"s4", "s3", "s2", "s1", "other"};
  p.matrix = {{0.8, 0.0, 0.1, 0.0, 0.1}, {0.0, 0.9, 0.0, 0.0, 0.1}, {0.1, 0.0, 0.9, 0.0, 0.0},
              {0.0, 0.0, 0.0, 0.5, 0.5}, {0.2, 0.2, 0.2, 0.2, 0.2}};
  const std::vector<Diagnostic> warnings = attach_predictions(r, {p});
  EXPECT_TRUE(warnings.empty());
  ASSERT_TRUE(r.sets[1].predicted);
  const PredictedComparison& c = *r.sets[1].predicted;
  // Row s1 (file row 4): 0.5 of 0.5 within the set -> 1. Row s4 (file row 1): 0.8, 0.1 of 0.9.
  EXPECT_DOUBLE_EQ(c.predicted[0][0], 1.0);
  EXPECT_NEAR(c.predicted[3][3], 0.8 / 0.9, 1e-15);
  EXPECT_NEAR(c.predicted[3][1], 0.1 / 0.9, 1e-15);
  EXPECT_NEAR(c.predicted[1][3], 0.1, 1e-15);
  EXPECT_DOUBLE_EQ(*c.measured[1][3], 0.03);
  EXPECT_EQ(c.off_diagonal_cells, 12u);
  // Off-diagonal: predicted 0.1 and 1/9 where 0.03 was measured (s2<->s4), 0 elsewhere.
  // SciPy 1.10.1's pearsonr([0.1, 0.1/0.9, 0 x 10], [0.03, 0.03, 0 x 10]).
  EXPECT_NEAR(*c.correlation, 0.9983420823082456, 1e-12);
  // The complexity set got the same prediction too (it names s1..s4 as well).
  EXPECT_TRUE(r.sets[0].predicted);
  // A prediction that names no set's images is reported.
  PredictedConfusion unrelated = p;
  unrelated.stems = {"q", "r", "s", "t", "u"};
  MatchingReport again = make_matching_report(paper_trials());
  EXPECT_EQ(attach_predictions(again, {unrelated}).size(), 1u);
}

// docs/studies.md: the correlation "is not defined when either side is the same in every such
// cell (for instance when nobody confused anything), and the report says so".
TEST(MatchingReport, CorrelationIsUndefinedWhenNothingWasConfusedAndTheReportSaysSo) {
  std::vector<MatchingTrial> trials;
  for (const std::string image : {"a", "b", "c"}) {
    MatchingTrial t;
    t.participant = "p01";
    t.set = "only";
    t.trial = static_cast<int>(trials.size()) + 1;
    t.presented = t.chosen = image;
    t.correct = true;
    trials.push_back(t);
  }
  PredictedConfusion p;
  p.source = "compare.json";
  p.stems = {"a", "b", "c"};
  p.matrix = {{0.8, 0.1, 0.1}, {0.2, 0.7, 0.1}, {0.0, 0.3, 0.7}};
  MatchingReport r = make_matching_report(trials);
  EXPECT_TRUE(attach_predictions(r, {p}).empty());
  ASSERT_TRUE(r.sets[0].predicted);
  const PredictedComparison& c = *r.sets[0].predicted;
  EXPECT_EQ(c.off_diagonal_cells, 6u);
  EXPECT_FALSE(c.correlation) << "every measured off-diagonal cell is 0";
  EXPECT_EQ(predicted_summary_text(c),
            "Prediction from compare.json. Pearson correlation of predicted and measured confusion over the 6 off-diagonal "
            "cells: r is not defined (one side is the same in every cell, e.g. no confusion was measured).");
  // The same with one confusion measured: defined, and 'r = ' with three decimals.
  trials[1].chosen = "c";
  trials[1].correct = false;
  MatchingReport confused = make_matching_report(trials);
  EXPECT_TRUE(attach_predictions(confused, {p}).empty());
  ASSERT_TRUE(confused.sets[0].predicted && confused.sets[0].predicted->correlation);
  EXPECT_NE(predicted_summary_text(*confused.sets[0].predicted).find("cells: r = "), std::string::npos);
}

}  // namespace
// A set whose prediction identifies an image less than 90 % of the time points to `vimg separate`
// (docs/separate.md); one at 90 % or more, or without a prediction, does not.
TEST(MatchingReport, ALowPredictedIdentificationPointsToVimgSeparate) {
  std::vector<MatchingTrial> trials;
  for (const std::string image : {"a", "b", "c"}) {
    MatchingTrial t;
    t.participant = "p01";
    t.set = "textures";
    t.trial = static_cast<int>(trials.size()) + 1;
    t.presented = t.chosen = image;
    t.correct = true;
    trials.push_back(t);
  }
  PredictedConfusion low;
  low.source = "compare.json";
  low.stems = {"a", "b", "c"};
  low.matrix = {{0.95, 0.05, 0.0}, {0.2, 0.67, 0.13}, {0.0, 0.05, 0.95}};
  MatchingReport r = make_matching_report(trials);
  EXPECT_FALSE(low_identification_warning(r.sets[0])) << "no prediction yet";
  ASSERT_TRUE(attach_predictions(r, {low}).empty());
  const auto w = low_identification_warning(r.sets[0]);
  ASSERT_TRUE(w);
  EXPECT_EQ(w->file, "compare.json");
  EXPECT_NE(w->message.find("set 'textures': the prediction identifies 'b' only 67 % of the time (below 90 %)"),
            std::string::npos)
      << w->message;
  EXPECT_NE(w->message.find("vimg separate"), std::string::npos);
  PredictedConfusion high = low;
  high.matrix = {{0.95, 0.05, 0.0}, {0.05, 0.9, 0.05}, {0.0, 0.05, 0.95}};
  MatchingReport distinct = make_matching_report(trials);
  ASSERT_TRUE(attach_predictions(distinct, {high}).empty());
  EXPECT_FALSE(low_identification_warning(distinct.sets[0]));
}

}  // namespace vimg::study
