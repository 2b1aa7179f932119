// `vimg serve --study` over raw sockets (web/study_server/study_service.hpp): an answer is checked
// against the participant's plan and appended through the trial log, with `correct` computed by
// the server; every refusal of the API (403, 400, 413, 405, 409, 429) writes nothing; the device
// record is written once.
#include <gtest/gtest.h>

#include <string>

#include "storage/study/trial_table.hpp"
#include "tests/study_server/study_fixture.hpp"

namespace vimg::test {
namespace {

TEST_F(StudyServer, AnAnswerIsCheckedAgainstThePlanAndAppendedWithCorrectComputed) {
  start();
  const std::string key = participant_key("p1");
  const HttpResponse state = get("/api/state?participant=p1", key);
  ASSERT_EQ(state.status, 200) << state.body;
  EXPECT_NE(state.body.find("\"trials\": 40"), std::string::npos) << state.body;
  EXPECT_NE(state.body.find("\"completed\": 0"), std::string::npos) << state.body;
  EXPECT_NE(state.body.find("\"instructions\": \"Each set of pictures begins with training"), std::string::npos) << state.body;

  // Trial 1 answered with another picture than the one presented, trial 2 with the right one.
  const std::string shown = presented("p1", 1);
  const std::string other = shown == stems_[study::plan_matching_trials(study_, "p1")[0].set][0]
                                ? stems_[study::plan_matching_trials(study_, "p1")[0].set][1]
                                : stems_[study::plan_matching_trials(study_, "p1")[0].set][0];
  HttpResponse reply = post("/api/answer", key, answer_body("p1", 1, shown, other));
  ASSERT_EQ(reply.status, 200) << reply.body;
  EXPECT_NE(reply.body.find("\"completed\": 1"), std::string::npos) << reply.body;
  reply = post("/api/answer", key, answer_body("p1", 2, presented("p1", 2), presented("p1", 2)));
  ASSERT_EQ(reply.status, 200) << reply.body;

  const auto table = read_matching_trials(trial_file("p1"));
  ASSERT_TRUE(table.ok());
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].participant, "p1");
  EXPECT_EQ(table.rows[0].trial, 1);
  EXPECT_EQ(table.rows[0].set, study_.sets[study::plan_matching_trials(study_, "p1")[0].set].name);
  EXPECT_EQ(table.rows[0].presented, shown);
  EXPECT_EQ(table.rows[0].chosen, other);
  EXPECT_FALSE(table.rows[0].correct);
  EXPECT_TRUE(table.rows[1].correct);
  EXPECT_EQ(table.rows[1].rub_s, 1.5);
  EXPECT_EQ(table.rows[1].response_s, 0.25);
  EXPECT_EQ(table.rows[1].path_mm, 12.5);

  // Already recorded, out of order, the wrong image presented, a choice not of the set.
  const std::string before = read_text(trial_file("p1"));
  reply = post("/api/answer", key, good_answer("p1", 2));
  EXPECT_EQ(reply.status, 409) << reply.body;
  EXPECT_NE(reply.body.find("\"completed\": 2"), std::string::npos) << reply.body;
  EXPECT_EQ(post("/api/answer", key, good_answer("p1", 4)).status, 409);
  std::string wrong = presented("p1", 3) == "dot" ? "line" : "dot";
  EXPECT_EQ(post("/api/answer", key, answer_body("p1", 3, wrong, wrong)).status, 400);
  EXPECT_EQ(post("/api/answer", key, answer_body("p1", 3, presented("p1", 3), "nosuchimage")).status, 400);
  EXPECT_EQ(read_text(trial_file("p1")), before);
}

TEST_F(StudyServer, EveryRefusalWritesNothing) {
  start();
  const std::string key = participant_key("p1");
  const std::string other_key = participant_key("p2");
  ASSERT_EQ(post("/api/answer", key, good_answer("p1", 1)).status, 200);
  const std::string before = read_text(trial_file("p1"));
  const std::string next = good_answer("p1", 2);

  // Keys: wrong, missing, another participant's; the researcher's is not a participant's.
  EXPECT_EQ(post("/api/answer", std::string(32, '0'), next).status, 403);
  EXPECT_EQ(post("/api/answer", "", next).status, 403);
  EXPECT_EQ(post("/api/answer", other_key, next).status, 403);
  EXPECT_EQ(post("/api/answer", researcher_key(), next).status, 403);
  EXPECT_EQ(get("/api/state?participant=p1", other_key).status, 403);
  EXPECT_EQ(get("/api/state?participant=p1", "").status, 403);
  // Origin: none, or another site's.
  EXPECT_EQ(post("/api/answer", key, next, "").status, 403);
  EXPECT_EQ(post("/api/answer", key, next, "http://evil.example").status, 403);
  EXPECT_EQ(post("/api/answer", key, next, "http://localhost.evil.example").status, 403);
  // Bodies over the bounds: the answer's own (2 KiB) and the server's (4 KiB).
  EXPECT_EQ(post("/api/answer", key, next + "&x=" + std::string(3000, 'a')).status, 413);
  EXPECT_EQ(post("/api/answer", key, next + "&x=" + std::string(5000, 'a')).status, 413);
  // Malformed bodies and rows.
  const std::string right = answer_body("p1", 2, presented("p1", 2), presented("p1", 2));
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = right;
    return text.replace(text.find(from), from.size(), to);
  };
  for (const std::string& bad :
       {std::string("not a form"), std::string(""), right + "&trial=2", right + "&extra=1", with("participant=p1", "participant=p1&"),
        right.substr(0, right.find("&path_mm")), with("trial=2", "trial=0"), with("trial=2", "trial=2.0"),
        with("trial=2", "trial=02"), right + "&device_user_agent=x", with("rub_s=1.5", "rub_s=nan"),
        with("rub_s=1.5", "rub_s=-1"), with("path_mm=12.5", "path_mm=1e300"), with("participant=p1", "participant=p%2F1")}) {
    const HttpResponse reply = post("/api/answer", key, bad);
    EXPECT_EQ(reply.status, 400) << bad << "\n" << reply.body;
  }
  // Every method but GET and HEAD elsewhere, and any but POST on the answer.
  EXPECT_EQ(exchange(port_, "PUT", "/api/answer", "X-Vimg-Key: " + key + "\r\nContent-Length: 0\r\n").status, 405);
  EXPECT_EQ(exchange(port_, "DELETE", "/api/answer").status, 405);
  EXPECT_EQ(get("/api/answer", key).status, 405);
  EXPECT_EQ(post("/api/state", key, next).status, 405);
  EXPECT_EQ(post("/index.html", key, next).status, 405);
  EXPECT_EQ(post("/api/answer/", key, next).status, 405);
  EXPECT_EQ(get("/api/nothing", key).status, 404);
  // The researcher's pages take the researcher's key only.
  for (const char* target : {"/api/progress", "/api/report", "/api/link?participant=p9"}) {
    EXPECT_EQ(get(target, "").status, 403) << target;
    EXPECT_EQ(get(target, key).status, 403) << target;
  }
  // What plain vimg serve refuses stays refused.
  EXPECT_EQ(exchange(port_, "GET", "/../results/p1.trials.csv").status, 403);
  EXPECT_EQ(exchange(port_, "GET", "/%2e%2e/results/p1.trials.csv").status, 403);
  EXPECT_EQ(read_text(trial_file("p1")), before);
  EXPECT_FALSE(std::filesystem::exists(trial_file("p2")));  // refused requests open no trial file
}

TEST_F(StudyServer, AnswersAreRateLimitedPerParticipant) {
  start();
  const std::string key = participant_key("p1");
  int limited = 0, answered = 0;
  for (int i = 0; i < 60; ++i) {
    const int status = post("/api/answer", key, good_answer("p1", 2)).status;  // out of order: 409 until limited
    if (status == 429) ++limited;
    if (status == 409) ++answered;
  }
  EXPECT_GT(limited, 0);
  EXPECT_EQ(limited + answered, 60);
  // Another participant is not limited by p1's answers.
  EXPECT_EQ(post("/api/answer", participant_key("p2"), good_answer("p2", 1)).status, 200);
}

TEST_F(StudyServer, TheDeviceIsRecordedOnceBesideTheTrialFile) {
  start();
  const std::string key = participant_key("p1");
  const std::string device =
      "&device_user_agent=Mozilla%2F5.0%20(Linux%2C%20Android)&device_screen_width_mm=70.5&device_screen_height_mm=150"
      "&device_audio_rate_hz=48000&device_output_latency_s=0.031";
  ASSERT_EQ(post("/api/answer", key, good_answer("p1", 1) + device).status, 200);
  const std::string record = read_text(results() / "p1.device.json");
  EXPECT_NE(record.find("\"user_agent\": \"Mozilla/5.0 (Linux, Android)\""), std::string::npos) << record;
  EXPECT_NE(record.find("\"screen_width_mm\": 70.5"), std::string::npos) << record;
  EXPECT_NE(record.find("\"audio_rate_hz\": 48000"), std::string::npos) << record;
  EXPECT_NE(record.find("\"output_latency_s\": 0.031"), std::string::npos) << record;
  std::string later = device;
  later.replace(later.find("70.5"), 4, "99.0");
  ASSERT_EQ(post("/api/answer", key, good_answer("p1", 2) + later).status, 200);
  EXPECT_EQ(read_text(results() / "p1.device.json"), record);
}

}  // namespace
}  // namespace vimg::test
