#include "storage/study/perception_model_file.hpp"

#include <cmath>
#include <iterator>

#include "storage/actuator_profile.hpp"
#include "storage/export/json_writer.hpp"
#include "storage/json_checker.hpp"
#include "storage/json_reader.hpp"
#include "storage/load_file.hpp"
#include "storage/number_text.hpp"

namespace vimg {

namespace {

void likelihoods(JsonWriter& w, const ModelLikelihoods& l) {
  w.begin_object();
  if (!l.participant.empty()) {
    w.key("participant");
    w.string(l.participant);
  }
  w.key("trials");
  w.number(l.trials);
  w.key("fitted");
  w.number(l.fitted);
  w.key("baseline");
  w.number(l.baseline);
  w.key("default");
  w.number(l.defaults);
  w.key("chance");
  w.number(l.chance);
  w.end_object();
}

void strings(JsonWriter& w, const std::vector<std::string>& texts) {
  w.begin_array();
  for (const std::string& t : texts) w.string(t);
  w.end_array();
}

// [lower, upper]; an infinite end is null.
void interval(JsonWriter& w, double lower, double upper) {
  w.begin_array();
  for (const double end : {lower, upper}) {
    if (std::isfinite(end)) {
      w.number(end);
    } else {
      w.null();
    }
  }
  w.end_array();
}

constexpr const char* kResponseNumbers[] = {"resonance_hz", "q", "low_hz", "high_hz", "spin_up_s", "spin_down_s"};

double& response_number(ResponseParams& r, std::size_t k) {
  double* fields[] = {&r.resonance_hz, &r.q, &r.low_hz, &r.high_hz, &r.spin_up_s, &r.spin_down_s};
  return *fields[k];
}

void response(JsonWriter& w, ResponseParams r) {
  w.begin_object();
  w.key("model");
  w.string(to_string(r.model));
  for (std::size_t k = 0; k < std::size(kResponseNumbers); ++k) {
    w.key(kResponseNumbers[k]);
    w.number(response_number(r, k));
  }
  w.end_object();
}

const JsonValue* find_member(JsonChecker& check, const JsonValue& object, std::string_view key, const std::string& where) {
  const JsonValue* v = object.find(key);
  if (!v) check.fail(object.line, where + " has no \"" + std::string(key) + "\" key");
  return v;
}

// A number of `v` within (low or [low, high]; high may be infinite).
bool in_range(JsonChecker& check, const JsonValue& v, const std::string& what, double low, bool low_open, double high, double& out) {
  if (!check.expect(v, JsonValue::Kind::number, what)) return false;
  const double x = v.number;
  const bool above = low_open ? x > low : x >= low;
  if (!(above && x <= high))
    return check.fail(v.line, what + " must be " + (low_open ? "> " : ">= ") + format_decimal(low) +
                                  (std::isinf(high) ? std::string() : " and <= " + format_decimal(high)));
  out = x;
  return true;
}

class Reader : public JsonChecker {
 public:
  explicit Reader(const std::string& file_name) : JsonChecker(file_name) {}

  const JsonValue* member(const JsonValue& object, std::string_view key, const std::string& where) {
    return find_member(*this, object, key, where);
  }

  bool header(const JsonValue& root) {
    if (!expect(root, JsonValue::Kind::object, "a perception model")) return false;
    const JsonValue* format = member(root, "format", "the file");
    if (!format || !expect(*format, JsonValue::Kind::string, "\"format\"")) return false;
    if (format->text != kPerceptionModelFormat)
      return fail(format->line, "\"format\" is \"" + escape_input(format->text) + "\", not \"" +
                                    std::string(kPerceptionModelFormat) + "\": not a perception model of vimg study fit");
    const JsonValue* version = member(root, "version", "the file");
    if (!version || !expect(*version, JsonValue::Kind::number, "\"version\"")) return false;
    if (!(version->number >= 1.0) || version->number != std::floor(version->number))
      return fail(version->line, "\"version\" must be a whole number from 1");
    if (version->number > kPerceptionModelVersion) {
      char text[48];
      std::snprintf(text, sizeof text, "%.0f", version->number);
      return fail(version->line, "the model is of version " + std::string(text) + ", a newer version than this vimg reads (" +
                                     std::to_string(kPerceptionModelVersion) + "); use a newer vimg");
    }
    return true;
  }

  bool constants(const JsonValue& root, DiscriminationConstants& out) {
    const JsonValue* c = member(root, "constants", "the file");
    if (!c || !expect(*c, JsonValue::Kind::object, "\"constants\"")) return false;
    for (std::size_t k = 0; k < c->keys.size(); ++k) {
      const std::string& key = c->keys[k];
      if (key != "temperature_jnd" && key != "lapse_rate" && key != "cue_weight")
        return fail(c->items[k].line, "unknown constant \"" + escape_input(key) +
                                          "\" (the constants are temperature_jnd, lapse_rate and cue_weight)");
    }
    return read_discrimination_constants(*this, *c, out);
  }

  bool fitted_on(const JsonValue& root, PerceptionModel& out) {
    const JsonValue* f = root.find("fitted_on");
    if (!f) return true;
    if (!expect(*f, JsonValue::Kind::object, "\"fitted_on\"")) return false;
    if (!optional_string(*f, "study", out.study) || !optional_string(*f, "actuator", out.actuator.given) ||
        !optional_string(*f, "actuator_name", out.actuator.name))
      return false;
    if (const JsonValue* given = f->find("actuator")) out.actuator.line = given->line;
    const JsonValue* r = f->find("actuator_response");
    if (!r) return true;
    ResponseParams params;
    if (!actuator_response(*r, params)) return false;
    out.actuator.response = params;
    if (out.actuator.line == 0) out.actuator.line = r->line;
    return true;
  }

 private:
  bool optional_string(const JsonValue& object, std::string_view key, std::string& out) {
    const JsonValue* v = object.find(key);
    if (!v) return true;
    if (!expect(*v, JsonValue::Kind::string, "\"" + std::string(key) + "\" of \"fitted_on\"")) return false;
    out = v->text;
    return true;
  }

  // {"model": "lra", "resonance_hz": ..., ...}: every key, each number > 0.
  bool actuator_response(const JsonValue& r, ResponseParams& out) {
    if (!expect(r, JsonValue::Kind::object, "\"actuator_response\"")) return false;
    const JsonValue* model = member(r, "model", "\"actuator_response\"");
    if (!model || !expect(*model, JsonValue::Kind::string, "\"model\" of \"actuator_response\"")) return false;
    bool known = false;
    for (const ResponseModel m : {ResponseModel::ideal, ResponseModel::lra, ResponseModel::erm, ResponseModel::voice_coil}) {
      if (model->text == to_string(m)) out.model = m, known = true;
    }
    if (!known)
      return fail(model->line, "unknown actuator model \"" + escape_input(model->text) + "\" (the models are ideal, lra, erm, voice_coil)");
    for (std::size_t k = 0; k < std::size(kResponseNumbers); ++k) {
      const JsonValue* v = member(r, kResponseNumbers[k], "\"actuator_response\"");
      if (!v || !in_range(*this, *v, "\"" + std::string(kResponseNumbers[k]) + "\"", 0.0, true, INFINITY, response_number(out, k)))
        return false;
    }
    return true;
  }

};

}  // namespace

bool read_discrimination_constants(JsonChecker& check, const JsonValue& object, DiscriminationConstants& out) {
  const double inf = INFINITY;
  const JsonValue* t = find_member(check, object, "temperature_jnd", "\"constants\"");
  if (!t || !in_range(check, *t, "\"temperature_jnd\"", 0.0, true, inf, out.temperature_jnd)) return false;
  const JsonValue* lapse = find_member(check, object, "lapse_rate", "\"constants\"");
  if (!lapse || !in_range(check, *lapse, "\"lapse_rate\"", 0.0, false, 1.0, out.lapse_rate)) return false;
  const JsonValue* w = find_member(check, object, "cue_weight", "\"constants\"");
  if (!w || !check.expect(*w, JsonValue::Kind::object, "\"cue_weight\"")) return false;
  std::string names;
  for (std::size_t cue = 0; cue < kCueCount; ++cue) names += (cue ? ", " : "") + std::string(cue_name(cue));
  for (std::size_t k = 0; k < w->keys.size(); ++k) {
    bool known = false;
    for (std::size_t cue = 0; cue < kCueCount; ++cue) known = known || w->keys[k] == cue_name(cue);
    if (!known) return check.fail(w->items[k].line, "unknown cue \"" + escape_input(w->keys[k]) + "\" (the cues are " + names + ")");
  }
  for (std::size_t cue = 0; cue < kCueCount; ++cue) {
    const std::string name(cue_name(cue));
    const JsonValue* v = find_member(check, *w, name, "\"cue_weight\"");
    if (!v || !in_range(check, *v, "the weight of cue \"" + name + "\"", 0.0, false, inf, out.cue_weight[cue])) return false;
  }
  return true;
}

void write_discrimination_constants(JsonWriter& w, const DiscriminationConstants& k) {
  w.key("temperature_jnd");
  w.number(k.temperature_jnd);
  w.key("lapse_rate");
  w.number(k.lapse_rate);
  w.key("cue_weight");
  w.begin_object();
  for (std::size_t cue = 0; cue < kCueCount; ++cue) {
    w.key(cue_name(cue));
    w.number(k.cue_weight[cue]);
  }
  w.end_object();
}

std::string perception_model_json(const PerceptionModel& m) {
  JsonWriter w;
  w.begin_object();
  w.key("format");
  w.string(kPerceptionModelFormat);
  w.key("version");
  w.integer(kPerceptionModelVersion);
  w.key("constants");
  w.begin_object();
  write_discrimination_constants(w, m.constants);
  w.end_object();
  w.key("fitted");
  strings(w, m.fitted);
  w.key("intervals");
  w.begin_object();
  w.key("confidence");
  w.number(m.interval_confidence);
  w.key("method");
  w.string("bootstrap over participants (percentile)");
  w.key("replicates");
  w.integer(static_cast<long long>(m.bootstrap_replicates));
  w.key("bounds");
  w.begin_object();
  for (const ModelInterval& i : m.intervals) {
    w.key(i.constant);
    interval(w, i.lower, i.upper);
  }
  w.end_object();
  w.key("profile_bounds");
  w.begin_object();
  for (const ModelInterval& i : m.intervals) {
    w.key(i.constant);
    interval(w, i.profile_lower, i.profile_upper);
  }
  w.end_object();
  w.end_object();
  w.key("fitted_on");
  w.begin_object();
  w.key("study");
  w.string(m.study);
  w.key("actuator");
  w.string(m.actuator.given);
  if (!m.actuator.name.empty()) {
    w.key("actuator_name");
    w.string(m.actuator.name);
  }
  if (m.actuator.response) {
    w.key("actuator_response");
    response(w, *m.actuator.response);
  }
  w.key("trial_files");
  strings(w, m.trial_files);
  w.key("participants");
  w.integer(static_cast<long long>(m.participants));
  w.key("trials");
  w.number(m.in_sample.trials);
  w.key("log_likelihood");
  likelihoods(w, m.in_sample);
  w.end_object();
  w.key("leave_one_participant_out");
  w.begin_object();
  w.key("participants");
  w.begin_array();
  for (const ModelLikelihoods& l : m.held_out) likelihoods(w, l);
  w.end_array();
  w.key("total");
  likelihoods(w, m.held_out_total);
  w.end_object();
  w.key("warnings");
  strings(w, m.warnings);
  w.end_object();
  return w.take();
}

PerceptionModelLoadResult parse_perception_model(std::string_view json, const std::string& file_name) {
  PerceptionModelLoadResult result;
  JsonParseResult parsed = parse_json(json, file_name);
  if (!parsed.value) {
    result.diagnostics = std::move(parsed.diagnostics);
    return result;
  }
  Reader read(file_name);
  PerceptionModel model;
  const JsonValue& root = *parsed.value;
  const bool ok = read.header(root) && read.constants(root, model.constants) && read.fitted_on(root, model);
  result.diagnostics = read.take();
  if (ok) result.model = std::move(model);
  return result;
}

PerceptionModelLoadResult load_perception_model(const std::filesystem::path& file) {
  return load_file<PerceptionModelLoadResult>(file, kMaxPerceptionModelBytes, parse_perception_model);
}

}  // namespace vimg
