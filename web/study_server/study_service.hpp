#pragma once
// The API of `vimg serve --study` (docs/studies.md, "In the browser"; docs/web.md, "A study in the
// browser"): what the study page and the dashboard ask of the server. Keys travel in the
// X-Vimg-Key header, never in a URL the server sees (links carry them after '#').
//
//   GET  /api/state?participant=ID   participant's key   the study, the plan, the trials done
//   POST /api/answer                 participant's key   one trial's row (answer_form.hpp)
//   GET  /api/progress               researcher's key    every participant's progress (JSON)
//   GET  /api/report                 researcher's key    `vimg study report`'s HTML of the results
//   GET  /api/link?participant=ID    researcher's key    that participant's key (the dashboard's links)
//
// The answer: a body over kMaxAnswerBodyBytes is 413; an Origin that is not this server's (or
// none) 403; a body that is not a well-formed answer 400; a wrong or missing key, or another
// participant's, 403; more than the participant's rate allows 429; a finished participant, or a
// trial that is not the next one, 409 (the reply says how many are done); an image that is not the
// plan's, or a choice not of the set, 400. Then the row is appended through TrialLog (one synced
// line; the participant's first accepted trial makes DIR/ID.trials.csv) and, after it, the device
// record is written once (DIR/ID.device.json, atomically): 200. A refused request, and GET
// /api/state, write nothing and make no file. A participant whose trial file exists but cannot be
// opened (held by vimg-player, say, or broken) gets 503 on the state and the answer. Other methods
// are 405 (POST only on /api/answer, GET and HEAD elsewhere); any other path under /api/ is 404.
// Threads: handle() is called from the server's workers at once.
#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "storage/study/study_file.hpp"
#include "study/trial_plan.hpp"
#include "web/server/web_server.hpp"
#include "web/study_server/participant_logs.hpp"
#include "web/study_server/study_keys.hpp"

namespace vimg::web {

class StudyService {
 public:
  // `image_names[s][i]`: the site's name of image i of set s (images/NAME.vsc).
  StudyService(MatchingStudy study, std::vector<std::vector<std::string>> image_names, std::filesystem::path results_dir,
               StudyKeys keys, std::function<void(const std::string&)> log_line = {});

  ApiReply handle(const ApiRequest& request);

  // The participants' trial files held open (WebServerOptions::api_files_held). Never waits.
  int open_trial_files() const { return logs_.open_logs(); }

  // The paths a POST may reach (WebServerOptions::api_post_paths).
  static std::vector<std::string> post_paths() { return {"/api/answer"}; }

 private:
  ApiReply state(const ApiRequest& request);
  ApiReply answer(const ApiRequest& request);
  ApiReply progress() const;
  ApiReply report() const;
  ApiReply link(const ApiRequest& request) const;
  void say(const std::string& line) const;

  MatchingStudy study_;
  std::vector<std::vector<std::string>> stems_;
  std::vector<std::vector<std::string>> image_names_;
  std::filesystem::path dir_;
  StudyKeys keys_;
  std::function<void(const std::string&)> log_line_;
  std::size_t total_ = 0;
  ParticipantLogs logs_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

// The trial files of the results folder a dashboard reports: DIR/ID.trials.csv for every valid
// participant ID (files kept aside by --restart are not), sorted by name.
std::vector<std::filesystem::path> participant_trial_files(const std::filesystem::path& dir);

}  // namespace vimg::web
