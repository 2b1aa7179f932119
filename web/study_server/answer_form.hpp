#pragma once
// A page's answer, as the server reads it before anything is written (docs/matching-test.md, "The matching test in the
// browser"). The body is form text (web/study_server/form_text.hpp) with exactly these fields:
//   participant, trial (1..N), presented, chosen (image stems of the trial's set), rub_s,
//   response_s, path_mm (decimal numbers, docs/format-studies.md "Trial files")
// and, all or none of them, the device the page runs on (written once per participant):
//   device_user_agent, device_screen_width_mm, device_screen_height_mm, device_audio_rate_hz,
//   device_output_latency_s
// The server's checks come in two steps: parse_answer (the body alone: 400 when malformed) and,
// once the trial is known to be the participant's next one, answer_result (the plan's image was
// presented and the choice is one of the set's: 400 otherwise). Pure.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "storage/study/study_file.hpp"
#include "study/study_flow.hpp"
#include "study/trial_plan.hpp"
#include "web/study_server/form_text.hpp"

namespace vimg::web {

// Bounds of what a page may send (the server refuses a longer body with 413).
inline constexpr std::size_t kMaxAnswerBodyBytes = 2048;
inline constexpr std::size_t kMaxUserAgentBytes = 512;

struct DeviceRecord {
  std::string user_agent;  // printable ASCII
  double screen_width_mm = 0.0, screen_height_mm = 0.0;  // from the page's calibration
  double audio_rate_hz = 0.0;
  double output_latency_s = 0.0;  // baseLatency + outputLatency as the browser reports them
};

struct ParsedAnswer {
  std::string participant;
  std::size_t trial = 0;
  std::string presented, chosen;
  double rub_s = 0.0, response_s = 0.0, path_mm = 0.0;
  std::optional<DeviceRecord> device;
};

// The answer, or the reason the body is malformed (error non-empty).
struct AnswerParse {
  std::optional<ParsedAnswer> answer;
  std::string error;
};
AnswerParse parse_answer(const FormFields& form, std::size_t total_trials);

// The trial's result from an answer whose trial is the next one (1 <= trial <= plan.size()), or
// the reason it is refused: the presented image is not the plan's, or the choice is not an image
// of the set. `stems[s][i]` names image i of set s.
struct AnswerCheck {
  std::optional<study::StudyTrialResult> result;
  std::string error;
};
AnswerCheck answer_result(const ParsedAnswer& answer, const std::vector<std::vector<std::string>>& stems,
                          const std::vector<study::MatchingTrialPlan>& plan);

}  // namespace vimg::web
