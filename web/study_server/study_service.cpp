#include "web/study_server/study_service.hpp"

#include <algorithm>
#include <cstdio>
#include <system_error>
#include <utility>

#include "storage/atomic_file.hpp"
#include "storage/export/json_writer.hpp"
#include "study/matching_row.hpp"
#include "study/report_inputs.hpp"
#include "study/report_writers.hpp"
#include "web/study_server/answer_form.hpp"
#include "web/study_server/device_record.hpp"

namespace vimg::web {

namespace {

namespace fs = std::filesystem;

ApiReply json_reply(int status, std::string json) { return body_reply(status, "application/json", std::move(json)); }

// An answer's outcome the page can act on: the reason it was refused (none when it was recorded)
// and how many trials are recorded.
ApiReply refusal(int status, const std::string& why, std::size_t completed, std::size_t total) {
  JsonWriter w;
  w.begin_object();
  if (!why.empty()) {
    w.key("error");
    w.string(why);
  }
  w.key("completed");
  w.integer(static_cast<long long>(completed));
  w.key("trials");
  w.integer(static_cast<long long>(total));
  w.end_object();
  return json_reply(status, w.take());
}

// Every image of every set `repetitions` times (study/trial_plan.hpp).
std::size_t count_trials(const MatchingStudy& study) {
  std::size_t images = 0;
  for (const auto& set : study.sets) images += set.images.size();
  return images * static_cast<std::size_t>(study.repetitions);
}

// The answer comes from this server's own page: Origin is http(s):// and the Host the request
// was sent to (behind a reverse proxy that keeps Host, the public name).
bool same_origin(const ApiRequest& request) {
  if (request.host.empty()) return false;
  return request.origin == "http://" + request.host || request.origin == "https://" + request.host;
}

// The participant of ?participant=ID, or nothing when the query has none that is valid.
std::optional<std::string> participant_of(const ApiRequest& request) {
  const FormFields query = parse_form_text(request.query);
  auto participant = query.get("participant");
  if (!query.ok() || !participant || !valid_participant_id(*participant)) return std::nullopt;
  return std::string(*participant);
}

ApiReply bad_participant() { return text_reply(400, "bad request: ?participant=ID (1 to 64 of A-Z a-z 0-9 _ -)"); }

}  // namespace

std::vector<fs::path> participant_trial_files(const fs::path& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    static constexpr std::string_view kSuffix = ".trials.csv";
    if (name.size() <= kSuffix.size() || name.compare(name.size() - kSuffix.size(), kSuffix.size(), kSuffix) != 0) continue;
    if (!valid_participant_id(name.substr(0, name.size() - kSuffix.size()))) continue;
    if (it->is_regular_file(ec) && !it->is_symlink(ec)) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

StudyService::StudyService(MatchingStudy study, std::vector<std::vector<std::string>> image_names, fs::path results_dir,
                           StudyKeys keys, std::function<void(const std::string&)> log_line)
    : study_(std::move(study)),
      stems_(study::matching_study_stems(study_)),
      image_names_(std::move(image_names)),
      dir_(std::move(results_dir)),
      keys_(keys),
      log_line_(std::move(log_line)),
      total_(count_trials(study_)),
      logs_(dir_, total_) {}

void StudyService::say(const std::string& line) const {
  if (log_line_) {
    log_line_(line);
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
}

StudyService::Checked StudyService::check(const ApiRequest& request) const {
  Checked c;
  const bool get = request.method == "GET" || request.method == "HEAD";
  if (request.path == "/api/answer") {
    if (request.method != "POST") return c.refuse(text_reply(405, "method not allowed: an answer is a POST"));
    if (request.body.size() > kMaxAnswerBodyBytes) {
      return c.refuse(text_reply(413, "payload too large: an answer is at most " + std::to_string(kMaxAnswerBodyBytes) + " bytes"));
    }
    if (!same_origin(request)) return c.refuse(text_reply(403, "forbidden: an answer must come from this server's own page (Origin)"));
    AnswerParse parsed = parse_answer(parse_form_text(request.body), total_);
    if (!parsed.answer) return c.refuse(text_reply(400, "bad request: " + parsed.error));
    if (!keys_.is_participant_key(parsed.answer->participant, request.field(kApiKeyField))) {
      return c.refuse(text_reply(403, "forbidden: wrong or missing key"));
    }
    c.answer = std::move(parsed.answer);
    return c;
  }
  if (!get) return c.refuse(text_reply(405, "method not allowed"));
  if (request.path == "/api/state") {
    const auto participant = participant_of(request);
    if (!participant) return c.refuse(bad_participant());
    if (!keys_.is_participant_key(*participant, request.field(kApiKeyField))) return c.refuse(text_reply(403, "forbidden: wrong or missing key"));
    c.participant = *participant;
    return c;
  }
  if (request.path == "/api/progress" || request.path == "/api/report" || request.path == "/api/link") {
    if (!keys_.is_researcher_key(request.field(kApiKeyField))) return c.refuse(text_reply(403, "forbidden: the researcher's key is wrong or missing"));
    if (request.path != "/api/link") return c;
    const auto participant = participant_of(request);
    if (!participant) return c.refuse(bad_participant());
    c.participant = *participant;
    return c;
  }
  return c.refuse(text_reply(404, "not found"));
}

std::optional<ApiReply> StudyService::screen(const ApiRequest& request) {
  Checked c = check(request);
  if (c.refused) return std::move(c.refused);
  if (!c.answer) return std::nullopt;
  const double now_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  if (!logs_.take_answer(c.answer->participant, now_s)) {  // never takes the participant's lock
    return text_reply(429, "too many requests: at most " + std::to_string(static_cast<int>(kAnswersPerSecond)) +
                               " answers a second");
  }
  return std::nullopt;
}

ApiReply StudyService::respond(const ApiRequest& request) {
  Checked c = check(request);
  if (c.refused) return std::move(*c.refused);
  if (c.answer) return answer(*c.answer);
  if (request.path == "/api/state") return state(c.participant);
  if (request.path == "/api/progress") return progress();
  if (request.path == "/api/report") return report();
  return link(c.participant);
}

ApiReply StudyService::handle(const ApiRequest& request) {
  if (auto refused = screen(request)) return std::move(*refused);
  return respond(request);
}

void StudyService::install(WebServerOptions& options) {
  options.api = [this](const ApiRequest& request) { return respond(request); };
  options.api_screen = [this](const ApiRequest& request) { return screen(request); };
  options.api_post_paths = post_paths();
  options.api_files_held = [this] { return open_trial_files(); };
}

ApiReply StudyService::state(const std::string& participant) {
  std::size_t completed = 0;
  bool finished = false;
  std::string error;
  logs_.with(participant, [&](ParticipantEntry& entry) {
    finished = entry.finished || entry.completed() == total_;
    completed = finished ? total_ : entry.completed();
    error = entry.error;
  });
  if (!error.empty()) {
    say("vimg serve: " + error);
    return text_reply(503, "the participant's trial file cannot be opened; the server's log says why");
  }
  const auto plan = study::plan_matching_trials(study_, participant);
  JsonWriter w;
  w.begin_object();
  w.key("participant");
  w.string(participant);
  w.key("trials");
  w.integer(static_cast<long long>(total_));
  w.key("completed");
  w.integer(static_cast<long long>(completed));
  w.key("finished");
  w.integer(finished ? 1 : 0);
  w.key("training_s");
  w.number(study_.training_minutes * 60.0);
  w.key("instructions");
  w.string(study_.instructions);
  w.key("consent");
  w.string(study_.consent);
  w.key("sets");
  w.begin_array();
  for (std::size_t s = 0; s < study_.sets.size(); ++s) {
    w.begin_object();
    w.key("name");
    w.string(study_.sets[s].name);
    w.key("images");
    w.begin_array();
    for (const std::string& stem : stems_[s]) w.string(stem);
    w.end_array();
    w.key("files");
    w.begin_array();
    for (const std::string& name : image_names_[s]) w.string(name);
    w.end_array();
    w.end_object();
  }
  w.end_array();
  w.key("plan");
  w.begin_array();
  for (const auto& trial : plan) {
    w.begin_array();
    w.integer(static_cast<long long>(trial.set));
    w.integer(static_cast<long long>(trial.image));
    w.end_array();
  }
  w.end_array();
  w.end_object();
  return json_reply(200, w.take());
}

ApiReply StudyService::answer(const ParsedAnswer& a) {
  ApiReply reply;
  logs_.with(a.participant, [&](ParticipantEntry& entry) {
    if (!entry.error.empty()) {
      say("vimg serve: " + entry.error);
      reply = text_reply(503, "the participant's trial file cannot be opened; the server's log says why");
      return;
    }
    const bool finished = entry.finished || entry.completed() == total_;
    const std::size_t completed = finished ? total_ : entry.completed();
    if (finished) {
      reply = refusal(409, "participant " + a.participant + " has finished all trials", completed, total_);
      return;
    }
    if (a.trial != completed + 1) {
      reply = refusal(409, "trial " + std::to_string(a.trial) + " is not the next one (" + std::to_string(completed + 1) + ")",
                      completed, total_);
      return;
    }
    const AnswerCheck check = answer_result(a, stems_, study::plan_matching_trials(study_, a.participant));
    if (!check.result) {
      reply = text_reply(400, "bad request: " + check.error);
      return;
    }
    const MatchingTrial row =
        study::matching_trial_row(study_, stems_, a.participant, *check.result, utc_timestamp_now());
    if (const auto error = logs_.append(a.participant, entry, to_cells(row))) {
      say("vimg serve: " + *error);
      reply = text_reply(500, "the trial cannot be written; the server's log says why");
      return;
    }
    // The device record follows the row it describes: a failed append leaves none. The row is
    // recorded either way; a record that cannot be written is tried again with the next answer.
    if (a.device) {
      if (const auto error = write_device_record_once(dir_, a.participant, *a.device)) say("vimg serve: " + *error);
    }
    reply = refusal(200, "", entry.completed(), total_);  // recorded
  });
  return reply;
}

ApiReply StudyService::progress() const {
  JsonWriter w;
  w.begin_object();
  w.key("trials");
  w.integer(static_cast<long long>(total_));
  w.key("participants");
  w.begin_array();
  for (const fs::path& file : participant_trial_files(dir_)) {
    const auto table = read_matching_trials(file);
    const std::string name = file.filename().string();
    w.begin_object();
    w.key("participant");
    w.string(name.substr(0, name.size() - std::string_view(".trials.csv").size()));
    w.key("completed");
    w.integer(static_cast<long long>(table.rows.size()));
    w.key("readable");
    w.integer(table.ok() ? 1 : 0);
    w.key("last_utc");
    w.string(table.rows.empty() ? "" : table.rows.back().time_utc);
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return json_reply(200, w.take());
}

ApiReply StudyService::report() const {
  const study::ReportInputs inputs = study::read_report_inputs(participant_trial_files(dir_), {});
  if (!inputs.ok()) {
    std::string text = "the trial files cannot be reported:";
    for (const Diagnostic& d : inputs.diagnostics) text += "\n" + d.to_string();
    return text_reply(500, text);
  }
  if (!inputs.has_trials()) return text_reply(404, "no trials yet");
  std::vector<Diagnostic> warnings;
  return body_reply(200, "text/html; charset=utf-8", study::report_html(study::make_study_report(inputs, warnings)));
}

ApiReply StudyService::link(const std::string& participant) const {
  JsonWriter w;
  w.begin_object();
  w.key("participant");
  w.string(participant);
  w.key("key");
  w.string(keys_.participant_key(participant));
  w.end_object();
  return json_reply(200, w.take());
}

}  // namespace vimg::web
