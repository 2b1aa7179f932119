// `vimg serve --study` as a black box over raw sockets, for what the HTTP layer and the API decide
// together (docs/web-study.md, "A study in the browser"): every method but GET and HEAD on the API's
// paths, and any but POST on the answer, is 405; the answer's bound on both sides (exactly
// kMaxAnswerBodyBytes is recorded, one byte more is 413, as is a body beyond the server's own
// bound) and checked before the key; the state and a link without a participant are 400. Nothing
// refused leaves a file.
#include <gtest/gtest.h>

#include <string>

#include "storage/study/trial_table.hpp"
#include "tests/study_server/study_fixture.hpp"
#include "web/server/web_server.hpp"
#include "web/study_server/answer_form.hpp"

namespace vimg::test {
namespace {

TEST_F(StudyServer, OtherMethodsOnTheApiAre405) {
  start();
  const std::string key = participant_key("p1");
  for (const char* method : {"PUT", "DELETE", "PATCH", "OPTIONS"}) {
    for (const char* target : {"/api/answer", "/api/state?participant=p1", "/api/progress", "/api/report",
                               "/api/link?participant=p1"}) {
      const HttpResponse reply = exchange(port_, method, target, "X-Vimg-Key: " + key + "\r\nContent-Length: 0\r\n");
      EXPECT_EQ(reply.status, 405) << method << " " << target;
    }
  }
  EXPECT_EQ(post("/api/progress", researcher_key(), "").status, 405);
  EXPECT_EQ(post("/api/link?participant=p1", researcher_key(), "").status, 405);
  EXPECT_EQ(exchange(port_, "HEAD", "/api/state?participant=p1", "X-Vimg-Key: " + key + "\r\n").status, 200);
  EXPECT_FALSE(std::filesystem::exists(trial_file("p1")));
}

TEST_F(StudyServer, TheAnswersBoundHoldsOnBothSidesBeforeTheKey) {
  start();
  const std::string key = participant_key("p1");
  // A well-formed answer of exactly kMaxAnswerBodyBytes: path_mm written with trailing zeros.
  const std::string exact = answer_of_size(good_answer("p1", 1), web::kMaxAnswerBodyBytes);
  const std::string one_more = answer_of_size(good_answer("p1", 1), web::kMaxAnswerBodyBytes + 1);
  ASSERT_EQ(exact.size(), web::kMaxAnswerBodyBytes);
  EXPECT_EQ(post("/api/answer", key, one_more).status, 413);
  EXPECT_EQ(post("/api/answer", std::string(32, '0'), one_more).status, 413) << "an oversized body with a wrong key";
  const std::string beyond_server = exact + "&x=" + std::string(web::kMaxRequestBodyBytes, 'a');
  EXPECT_EQ(post("/api/answer", std::string(32, '0'), beyond_server).status, 413) << "beyond the server's bound";
  EXPECT_FALSE(std::filesystem::exists(trial_file("p1")));
  const HttpResponse accepted = post("/api/answer", key, exact);
  ASSERT_EQ(accepted.status, 200) << accepted.body;
  const auto table = read_matching_trials(trial_file("p1"));
  ASSERT_TRUE(table.ok());
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.rows[0].path_mm, 12.5);
}

TEST_F(StudyServer, StateAndLinkWithoutAParticipantAre400) {
  start();
  for (const char* query : {"", "?participant=", "?participant=a%2Fb", "?who=p1"}) {
    EXPECT_EQ(get(std::string("/api/state") + query, participant_key("p1")).status, 400) << query;
    EXPECT_EQ(get(std::string("/api/link") + query, researcher_key()).status, 400) << query;
  }
  EXPECT_FALSE(std::filesystem::exists(trial_file("p1")));
}

}  // namespace
}  // namespace vimg::test
