// The prediction that `vimg study report --predicted` reads carries the model it was made with:
// the constants of `model` and the MODEL.json of `vimg compare --model` (storage/study/
// predicted_confusion.hpp), and the report names them beside the prediction.
#include <gtest/gtest.h>

#include <string>

#include "storage/study/predicted_confusion.hpp"
#include "study/report_predicted.hpp"
#include "study/report_tables.hpp"

namespace vimg {
namespace {

std::string compare_report(const std::string& model) {
  return "{\"images\": [\"a.vimg\", \"b.vimg\"],\n\"predicted_confusion\": [[0.75, 0.25], [0.25, 0.75]],\n\"model\": " + model + "}\n";
}

TEST(PredictedModel, TheConstantsAndTheModelFileAreReadAndNamedInTheReport) {
  const PredictedLoadResult r = parse_predicted_confusion(
      compare_report("{\"model_file\": \"fit/model.json\", \"temperature_jnd\": 0.5, \"lapse_rate\": 0.125,\n"
                     "\"cue_weight\": {\"level\": 2, \"pitch\": 0.25, \"envelope\": 1}}"),
      "c.json");
  ASSERT_TRUE(r.predicted) << r.diagnostics[0].to_string();
  ASSERT_TRUE(r.predicted->constants);
  EXPECT_EQ(r.predicted->constants->temperature_jnd, 0.5);
  EXPECT_EQ(r.predicted->constants->lapse_rate, 0.125);
  EXPECT_EQ(r.predicted->constants->cue_weight, (std::array<double, kCueCount>{2.0, 0.25, 1.0}));
  EXPECT_EQ(r.predicted->model_file, "fit/model.json");

  study::MatchingReport report;
  study::SetReport set;
  set.name = "s";
  set.images = {"a", "b"};
  set.comparison = {{3, 1}, {2, 2}};
  report.sets.push_back(set);
  EXPECT_TRUE(study::attach_predictions(report, {*r.predicted}).empty());
  ASSERT_TRUE(report.sets[0].predicted);
  const std::string summary = study::predicted_summary_text(*report.sets[0].predicted);
  EXPECT_EQ(summary.rfind("Prediction from c.json, made with the model fit/model.json (temperature 0.5 JND, lapse rate 0.125, "
                          "cue weights level 2, pitch 0.25, envelope 1). ",
                          0),
            0u)
      << summary;
}

TEST(PredictedModel, AReportWithoutTheModelsConstantsStillReads) {
  const PredictedLoadResult r = parse_predicted_confusion(compare_report("{\"model_file\": null, \"tau\": 0.1}"), "old.json");
  ASSERT_TRUE(r.predicted);
  EXPECT_FALSE(r.predicted->constants);
  EXPECT_TRUE(r.predicted->model_file.empty());
}

TEST(PredictedModel, MalformedConstantsAreAnErrorAtTheirLine) {
  const PredictedLoadResult r = parse_predicted_confusion(
      compare_report("{\"temperature_jnd\": 1, \"lapse_rate\": 0,\n\"cue_weight\": {\"level\": 1, \"pitch\": \"x\", \"envelope\": 1}}"),
      "c.json");
  EXPECT_FALSE(r.predicted);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "c.json:4: error: the weight of cue \"pitch\" must be a number, not a string");
  const PredictedLoadResult lapse =
      parse_predicted_confusion(compare_report("{\"temperature_jnd\": 1,\n\"lapse_rate\": 2, \"cue_weight\": {}}"), "c.json");
  ASSERT_EQ(lapse.diagnostics.size(), 1u);
  EXPECT_EQ(lapse.diagnostics[0].to_string(), "c.json:4: error: \"lapse_rate\" must be >= 0 and <= 1");
}

}  // namespace
}  // namespace vimg
