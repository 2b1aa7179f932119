#pragma once
// The API of `vimg serve --study` (docs/matching-test.md, "The matching test in the browser"; docs/web-study.md, "A study in the
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
// Every refusal up to the rate limit's 429 costs no file and no participant's lock: the server
// makes them on its network thread as the request arrives (screen()), before it waits for anything
// (a worker, the participant's turn, the participant's answer being synced); the rest is
// respond()'s, on a worker.
// Threads: screen() on the network thread, respond() on the server's workers at once.
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "storage/study/study_file.hpp"
#include "study/trial_plan.hpp"
#include "web/server/web_server.hpp"
#include "web/study_server/answer_form.hpp"
#include "web/study_server/participant_logs.hpp"
#include "web/study_server/study_keys.hpp"

namespace vimg::web {

class StudyService {
 public:
  // `image_names[s][i]`: the site's name of image i of set s (images/NAME.vsc).
  StudyService(MatchingStudy study, std::vector<std::vector<std::string>> image_names, std::filesystem::path results_dir,
               StudyKeys keys, std::function<void(const std::string&)> log_line = {});

  // The refusals that cost no file and no participant's lock, in the order above, the rate
  // limit's 429 last (it takes one answer from the participant's bucket): a reply, or nothing to go
  // on to respond().
  std::optional<ApiReply> screen(const ApiRequest& request);
  // The reply to a request screen() let through (its checks are made again, the rate's aside).
  ApiReply respond(const ApiRequest& request);
  // screen() then respond(): the whole API in one call (tests).
  ApiReply handle(const ApiRequest& request);
  // Serves through `options`: the api, its screen, the POST paths, the files held.
  void install(WebServerOptions& options);

  // The participants' trial files held open (WebServerOptions::api_files_held). Never waits.
  int open_trial_files() const { return logs_.open_logs(); }

  // The paths a POST may reach (WebServerOptions::api_post_paths).
  static std::vector<std::string> post_paths() { return {"/api/answer"}; }

 private:
  // What a request asks once the checks that cost no file and no participant's lock have passed,
  // or its refusal.
  struct Checked {
    std::optional<ApiReply> refused;
    std::optional<ParsedAnswer> answer;  // POST /api/answer
    std::string participant;             // /api/state, /api/link
    Checked& refuse(ApiReply reply) {
      refused = std::move(reply);
      return *this;
    }
  };
  Checked check(const ApiRequest& request) const;
  ApiReply state(const std::string& participant);
  ApiReply answer(const ParsedAnswer& answer);
  ApiReply progress() const;
  ApiReply report() const;
  ApiReply link(const std::string& participant) const;
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
