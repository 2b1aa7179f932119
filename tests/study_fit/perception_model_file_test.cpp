// MODEL.json (storage/study/perception_model_file.hpp): what the writer writes reads back to the
// same constants, and every malformed file, or one of a newer version, is one located error.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "storage/study/perception_model_file.hpp"
#include "tests/export/json_reader.hpp"

namespace vimg {
namespace {

std::string model_text(const std::string& constants, const std::string& version = "1") {
  return "{\n  \"format\": \"vimg-perception-model\",\n  \"version\": " + version + ",\n  \"constants\": " + constants + "\n}\n";
}

constexpr const char* kGoodConstants =
    "{\"temperature_jnd\": 0.9, \"lapse_rate\": 0.05,\n  \"cue_weight\": {\"level\": 1.5, \"pitch\": 0.25, \"envelope\": 2}}";

std::string only_error(const PerceptionModelLoadResult& r) {
  EXPECT_FALSE(r.model.has_value());
  EXPECT_EQ(r.diagnostics.size(), 1u);
  return r.diagnostics.empty() ? std::string() : r.diagnostics.front().to_string();
}

TEST(PerceptionModelFile, WhatTheWriterWritesReadsBackExactly) {
  PerceptionModel m;
  m.constants.temperature_jnd = 0.1 + 0.2;  // not a short decimal
  m.constants.lapse_rate = 1.0 / 3.0;
  m.constants.cue_weight = {std::sqrt(2.0), 0.0, 1e-7};
  m.fitted = {"lapse_rate", "cue_weight.level"};
  m.intervals = {{"lapse_rate", 0.2, 0.4, 0.25, 0.35}, {"cue_weight.level", 1.2, INFINITY, 1.3, INFINITY}};
  m.bootstrap_replicates = 1000;
  m.study = "studies/a \"quoted\" study.xml";
  m.actuator.given = "profiles/my lra.xml";
  m.actuator.name = "my-lra";
  ResponseParams lra;
  lra.model = ResponseModel::lra;
  lra.resonance_hz = 170.0 + 1.0 / 3.0;
  lra.q = 12.5;
  m.actuator.response = lra;
  m.trial_files = {"P1.trials.csv", "P2.trials.csv"};
  m.participants = 2;
  m.in_sample = {"", 80, -50.5, -60.5, -70.25, -110.9};
  m.held_out = {{"P1", 40, -26, -30, -35, -55.45}, {"P2", 40, -27, -30.5, -35.25, -55.45}};
  m.held_out_total = {"", 80, -53, -60.5, -70.25, -110.9};
  m.warnings = {"cue_weight.pitch: kept"};
  const std::string text = perception_model_json(m);
  const PerceptionModelLoadResult back = parse_perception_model(text, "m.json");
  ASSERT_TRUE(back.model) << (back.diagnostics.empty() ? "" : back.diagnostics[0].to_string());
  EXPECT_EQ(back.model->constants.temperature_jnd, m.constants.temperature_jnd);
  EXPECT_EQ(back.model->constants.lapse_rate, m.constants.lapse_rate);
  EXPECT_EQ(back.model->constants.cue_weight, m.constants.cue_weight);
  EXPECT_EQ(back.model->study, m.study);
  EXPECT_EQ(back.model->actuator.given, m.actuator.given);
  EXPECT_EQ(back.model->actuator.name, m.actuator.name);
  ASSERT_TRUE(back.model->actuator.response);
  EXPECT_EQ(back.model->actuator.response->model, ResponseModel::lra);
  EXPECT_EQ(back.model->actuator.response->resonance_hz, lra.resonance_hz);
  EXPECT_EQ(back.model->actuator.response->q, lra.q);
  EXPECT_EQ(back.model->actuator.response->spin_down_s, lra.spin_down_s);
  EXPECT_GT(back.model->actuator.line, 1);
  // The record, read with an independent JSON reader: the documented keys and values.
  const test::Json j = test::JsonReader::parse(text);
  EXPECT_EQ(j["format"].string(), "vimg-perception-model");
  EXPECT_EQ(j["version"].number(), 1.0);
  EXPECT_EQ(j["fitted"].array().size(), 2u);
  EXPECT_EQ(j["intervals"]["confidence"].number(), 0.95);
  EXPECT_EQ(j["intervals"]["method"].string(), "bootstrap over participants (percentile)");
  EXPECT_EQ(j["intervals"]["replicates"].number(), 1000.0);
  EXPECT_EQ(j["intervals"]["bounds"]["lapse_rate"].array()[1].number(), 0.4);
  EXPECT_EQ(j["intervals"]["bounds"]["cue_weight.level"].array()[0].number(), 1.2);
  EXPECT_TRUE(std::holds_alternative<std::nullptr_t>(j["intervals"]["bounds"]["cue_weight.level"].array()[1].value));  // unbounded: at least 1.2
  EXPECT_EQ(j["intervals"]["profile_bounds"]["lapse_rate"].array()[0].number(), 0.25);
  EXPECT_EQ(j["fitted_on"]["actuator_response"]["model"].string(), "lra");
  EXPECT_EQ(j["fitted_on"]["actuator_response"]["q"].number(), 12.5);
  EXPECT_EQ(j["fitted_on"]["log_likelihood"]["baseline"].number(), -60.5);
  EXPECT_EQ(j["fitted_on"]["participants"].number(), 2.0);
  EXPECT_EQ(j["fitted_on"]["log_likelihood"]["default"].number(), -70.25);
  EXPECT_EQ(j["leave_one_participant_out"]["participants"].array()[1]["participant"].string(), "P2");
  EXPECT_EQ(j["leave_one_participant_out"]["total"]["fitted"].number(), -53.0);
  EXPECT_EQ(j["warnings"].array()[0].string(), "cue_weight.pitch: kept");
}

TEST(PerceptionModelFile, ReadsTheConstantsOfAHandWrittenFile) {
  const PerceptionModelLoadResult r = parse_perception_model(model_text(kGoodConstants), "m.json");
  ASSERT_TRUE(r.model);
  EXPECT_EQ(r.model->constants.temperature_jnd, 0.9);
  EXPECT_EQ(r.model->constants.lapse_rate, 0.05);
  EXPECT_EQ(r.model->constants.cue_weight, (std::array<double, kCueCount>{1.5, 0.25, 2.0}));
  EXPECT_TRUE(r.model->study.empty());
}

// A model of an older vimg records the actuator as given only: it still reads, with no response.
TEST(PerceptionModelFile, AnOlderModelWithoutTheActuatorsResponseStillReads) {
  const std::string text = "{\n  \"format\": \"vimg-perception-model\",\n  \"version\": 1,\n  \"constants\": " +
                           std::string(kGoodConstants) + ",\n  \"fitted_on\": {\"study\": \"s.xml\",\n  \"actuator\": \"erm-10mm\"}\n}\n";
  const PerceptionModelLoadResult r = parse_perception_model(text, "m.json");
  ASSERT_TRUE(r.model) << r.diagnostics[0].to_string();
  EXPECT_EQ(r.model->actuator.given, "erm-10mm");
  EXPECT_TRUE(r.model->actuator.name.empty());
  EXPECT_FALSE(r.model->actuator.response);
  EXPECT_EQ(r.model->actuator.line, 7);
}

TEST(PerceptionModelFile, AMalformedActuatorResponseIsALocatedError) {
  const auto error = [](const std::string& response) {
    return only_error(parse_perception_model("{\"format\": \"vimg-perception-model\", \"version\": 1, \"constants\": " +
                                                 std::string(kGoodConstants) + ",\n\"fitted_on\": {\"actuator_response\":\n" +
                                                 response + "}}",
                                             "m.json"));
  };
  EXPECT_EQ(error("{\"model\": \"piezo\"}"), "m.json:4: error: unknown actuator model \"piezo\" (the models are ideal, lra, erm, voice_coil)");
  EXPECT_EQ(error("{\"model\": \"lra\", \"resonance_hz\": 175}"), "m.json:4: error: \"actuator_response\" has no \"q\" key");
  EXPECT_EQ(error("{\"model\": \"lra\", \"resonance_hz\": 0, \"q\": 1}"), "m.json:4: error: \"resonance_hz\" must be > 0");
  EXPECT_EQ(error("[1]"), "m.json:4: error: \"actuator_response\" must be an object, not an array");
}

TEST(PerceptionModelFile, ANewerVersionIsRefusedAtItsLine) {
  EXPECT_EQ(only_error(parse_perception_model(model_text(kGoodConstants, "2"), "m.json")),
            "m.json:3: error: the model is of version 2, a newer version than this vimg reads (1); use a newer vimg");
}

TEST(PerceptionModelFile, EveryMalformedFileIsOneLocatedError) {
  const auto error = [](const std::string& text) { return only_error(parse_perception_model(text, "m.json")); };
  EXPECT_EQ(error("{\"format\": \"vimg-perception-model\",\n\"version\": 1,\n\"constants\": {,}}"),
            "m.json:3: error: expected a member name in quotes, found ','");
  EXPECT_EQ(error("[1]"), "m.json:1: error: a perception model must be an object, not an array");
  EXPECT_EQ(error("{\"format\": \"vimg-compare\", \"version\": 1}"),
            "m.json:1: error: \"format\" is \"vimg-compare\", not \"vimg-perception-model\": not a perception model of vimg study fit");
  EXPECT_EQ(error("{\"version\": 1}"), "m.json:1: error: the file has no \"format\" key");
  EXPECT_EQ(error(model_text(kGoodConstants, "1.5")), "m.json:3: error: \"version\" must be a whole number from 1");
  EXPECT_EQ(error(model_text("{\"temperature_jnd\": 0, \"lapse_rate\": 0, \"cue_weight\": {}}")),
            "m.json:4: error: \"temperature_jnd\" must be > 0");
  EXPECT_EQ(error(model_text("{\"temperature_jnd\": 1, \"lapse_rate\": 1.5, \"cue_weight\": {}}")),
            "m.json:4: error: \"lapse_rate\" must be >= 0 and <= 1");
  EXPECT_EQ(error(model_text("{\"temperature_jnd\": 1, \"lapse_rate\": 0,\n\"cue_weight\": {\"level\": 1, \"pitch\": 1}}")),
            "m.json:5: error: \"cue_weight\" has no \"envelope\" key");
  EXPECT_EQ(error(model_text("{\"temperature_jnd\": 1, \"lapse_rate\": 0,\n\"cue_weight\": {\"level\": 1, \"pitch\": -1, "
                             "\"envelope\": 1}}")),
            "m.json:5: error: the weight of cue \"pitch\" must be >= 0");
  EXPECT_EQ(error(model_text("{\"temperature_jnd\": 1, \"lapse_rate\": 0,\n\"cue_weight\": {\"level\": 1, \"roughness\": 1}}")),
            "m.json:5: error: unknown cue \"roughness\" (the cues are level, pitch, envelope)");
  EXPECT_EQ(error(model_text("{\"temperature_jnd\": 1, \"tau\": 0.1}")),
            "m.json:4: error: unknown constant \"tau\" (the constants are temperature_jnd, lapse_rate and cue_weight)");
  EXPECT_EQ(error(model_text("{\"temperature_jnd\": \"1\"}")), "m.json:4: error: \"temperature_jnd\" must be a number, not a string");
  EXPECT_EQ(error("{\"format\": \"vimg-perception-model\", \"version\": 1}"), "m.json:1: error: the file has no \"constants\" key");
}

}  // namespace
}  // namespace vimg
