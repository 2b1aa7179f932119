#include "web/study_server/answer_form.hpp"

#include <charconv>
#include <cmath>
#include <set>
#include <variant>

#include "storage/number_text.hpp"
#include "storage/study/trial_log.hpp"

namespace vimg::web {

namespace {

const std::set<std::string> kRowFields{"participant", "trial", "presented", "chosen", "rub_s", "response_s", "path_mm"};
const std::set<std::string> kDeviceFields{"device_user_agent", "device_screen_width_mm", "device_screen_height_mm",
                                          "device_audio_rate_hz", "device_output_latency_s"};

// A decimal number in [low, high], or an error naming the field.
bool read_number(const FormFields& form, const std::string& name, double low, double high, double& value,
                 std::string& error) {
  const auto text = form.get(name);
  if (!text) {
    error = "field '" + name + "' is missing";
    return false;
  }
  const ParsedNumber parsed = parse_decimal(*text);
  if (const auto* why = std::get_if<std::string>(&parsed)) {
    error = name + " " + *why;
    return false;
  }
  value = std::get<double>(parsed);
  if (!(value >= low && value <= high)) {
    error = name + " is outside " + format_decimal(low) + ".." + format_decimal(high);
    return false;
  }
  return true;
}

bool printable_ascii(const std::string& text) {
  for (const char c : text) {
    if (c < 0x20 || c > 0x7E) return false;
  }
  return true;
}

}  // namespace

AnswerParse parse_answer(const FormFields& form, std::size_t total_trials) {
  AnswerParse out;
  if (!form.ok()) {
    out.error = "the body is not form text: " + form.error;
    return out;
  }
  std::size_t device_fields = 0;
  for (const auto& [name, value] : form.fields) {
    if (kDeviceFields.count(name)) {
      ++device_fields;
    } else if (!kRowFields.count(name)) {
      out.error = "unknown field '" + name + "'";
      return out;
    }
  }
  for (const std::string& name : kRowFields) {
    if (!form.get(name)) {
      out.error = "field '" + name + "' is missing";
      return out;
    }
  }
  if (device_fields != 0 && device_fields != kDeviceFields.size()) {
    out.error = "the device fields come all together or not at all";
    return out;
  }
  ParsedAnswer a;
  a.participant = *form.get("participant");
  if (!valid_participant_id(a.participant)) {
    out.error = "participant is not 1 to 64 of A-Z a-z 0-9 _ -";
    return out;
  }
  const std::string trial = *form.get("trial");
  const auto [end, ec] = std::from_chars(trial.data(), trial.data() + trial.size(), a.trial);
  if (ec != std::errc() || end != trial.data() + trial.size() || trial.empty() || trial[0] == '0' || a.trial > total_trials) {
    out.error = "trial is not a whole number from 1 to " + std::to_string(total_trials);
    return out;
  }
  a.presented = *form.get("presented");
  a.chosen = *form.get("chosen");
  std::string error;
  constexpr double kDay_s = 86400.0, kMaxPath_mm = 1e7;
  if (!read_number(form, "rub_s", 0.0, kDay_s, a.rub_s, error) ||
      !read_number(form, "response_s", 0.0, kDay_s, a.response_s, error) ||
      !read_number(form, "path_mm", 0.0, kMaxPath_mm, a.path_mm, error)) {
    out.error = error;
    return out;
  }
  if (device_fields != 0) {
    DeviceRecord d;
    d.user_agent = *form.get("device_user_agent");
    if (d.user_agent.size() > kMaxUserAgentBytes || !printable_ascii(d.user_agent)) {
      out.error = "device_user_agent is not at most " + std::to_string(kMaxUserAgentBytes) + " printable ASCII characters";
      return out;
    }
    if (!read_number(form, "device_screen_width_mm", 1.0, 10000.0, d.screen_width_mm, error) ||
        !read_number(form, "device_screen_height_mm", 1.0, 10000.0, d.screen_height_mm, error) ||
        !read_number(form, "device_audio_rate_hz", 0.0, 768000.0, d.audio_rate_hz, error) ||
        !read_number(form, "device_output_latency_s", 0.0, 10.0, d.output_latency_s, error)) {
      out.error = error;
      return out;
    }
    a.device = d;
  }
  out.answer = std::move(a);
  return out;
}

AnswerCheck answer_result(const ParsedAnswer& answer, const std::vector<std::vector<std::string>>& stems,
                          const std::vector<study::MatchingTrialPlan>& plan) {
  AnswerCheck out;
  const study::MatchingTrialPlan& planned = plan.at(answer.trial - 1);
  const std::vector<std::string>& set = stems.at(planned.set);
  if (answer.presented != set[planned.image]) {
    out.error = "trial " + std::to_string(answer.trial) + " presents " + set[planned.image] + ", not '" +
                escape_input(answer.presented) + "'";
    return out;
  }
  std::size_t chosen = set.size();
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (set[i] == answer.chosen) chosen = i;
  }
  if (chosen == set.size()) {
    out.error = "'" + escape_input(answer.chosen) + "' is not an image of the trial's set";
    return out;
  }
  study::StudyTrialResult r;
  r.trial = answer.trial;
  r.set = planned.set;
  r.presented = planned.image;
  r.chosen = chosen;
  r.rub_s = answer.rub_s;
  r.response_s = answer.response_s;
  r.path_mm = answer.path_mm;
  out.result = r;
  return out;
}

}  // namespace vimg::web
