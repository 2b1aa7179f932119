// The study API where its decisions are made (StudyService::handle, no sockets): a refused request
// or a state request writes nothing and makes no file, for every kind of refusal and a participant
// never seen before; the first accepted trial makes the trial file; the device record follows the
// row (a failed append leaves none); a trial file held by another program is 503; the requests
// without a participant (400), the methods (405), the body's bound on both sides and the order of
// the checks (docs/web-study.md, "A study in the browser"); the Origin of a page behind a TLS proxy. And
// the rate limit's bucket at given times.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "storage/study/trial_log.hpp"
#include "storage/study/trial_table.hpp"
#include "tests/study_server/study_fixture.hpp"
#include "web/study_server/answer_form.hpp"
#include "web/study_server/participant_logs.hpp"
#include "web/study_server/study_service.hpp"

namespace vimg::test {
namespace {

namespace fs = std::filesystem;

// 20 at once (kAnswerBurst), then one every 0.25 s (kAnswersPerSecond); the times are exact in binary.
TEST(RateBucket, AllowsTheBurstThenRefillsAtTheRateUpToTheCap) {
  web::RateBucket bucket(web::kAnswerBurst, web::kAnswersPerSecond);
  ASSERT_EQ(web::kAnswerBurst, 20.0);
  ASSERT_EQ(web::kAnswersPerSecond, 4.0);
  for (int i = 0; i < 20; ++i) EXPECT_TRUE(bucket.take(0.0)) << "request " << i + 1 << " of the burst";
  EXPECT_FALSE(bucket.take(0.0)) << "the 21st at once";
  // Half a token after 0.125 s is not enough; a whole one after 0.25 s is, and only one.
  EXPECT_FALSE(bucket.take(0.125));
  EXPECT_TRUE(bucket.take(0.25));
  EXPECT_FALSE(bucket.take(0.25));
  // 2.5 s later: 10 tokens.
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(bucket.take(2.75)) << "refilled token " << i + 1;
  EXPECT_FALSE(bucket.take(2.75));
  // A steady 4 a second is never refused.
  for (int k = 1; k <= 40; ++k) EXPECT_TRUE(bucket.take(2.75 + 0.25 * k)) << "steady request " << k;
  // After an hour's idle the bucket holds its capacity, not more.
  for (int i = 0; i < 20; ++i) EXPECT_TRUE(bucket.take(3600.0)) << "request " << i + 1 << " after the idle";
  EXPECT_FALSE(bucket.take(3600.0));
}

class StudyServiceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(VIMG_BINARY_DIR) / "study_server_tests" /
           (std::string("StudyService.") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    auto loaded = load_matching_study(kExampleStudy);
    ASSERT_TRUE(loaded.ok());
    study_ = *loaded.study;
    secret_[0] = 42;
  }

  web::StudyService service(const MatchingStudy& study) const {
    std::vector<std::vector<std::string>> names;
    for (const auto& stems : study::matching_study_stems(study)) names.push_back(stems);
    return web::StudyService(study, names, dir_, web::StudyKeys(secret_), [](const std::string&) {});
  }
  std::string key(const std::string& participant) const { return web::StudyKeys(secret_).participant_key(participant); }
  std::string researcher_key() const { return web::StudyKeys(secret_).researcher_key(); }

  std::string presented(const std::string& participant, std::size_t trial) const {
    const auto plan = study::plan_matching_trials(study_, participant);
    return study::matching_study_stems(study_)[plan[trial - 1].set][plan[trial - 1].image];
  }
  std::string other_of_set(const std::string& participant, std::size_t trial) const {
    const auto plan = study::plan_matching_trials(study_, participant);
    const auto stems = study::matching_study_stems(study_)[plan[trial - 1].set];
    return stems[plan[trial - 1].image == 0 ? 1 : 0];
  }
  static std::string body(const std::string& participant, std::size_t trial, const std::string& presented,
                          const std::string& chosen, const std::string& path_mm = "12.5") {
    return "participant=" + participant + "&trial=" + std::to_string(trial) + "&presented=" + presented +
           "&chosen=" + chosen + "&rub_s=1.5&response_s=0.25&path_mm=" + path_mm;
  }
  std::string good(const std::string& participant, std::size_t trial) const {
    return body(participant, trial, presented(participant, trial), presented(participant, trial));
  }
  static constexpr const char* kDevice =
      "&device_user_agent=test&device_screen_width_mm=70&device_screen_height_mm=150&device_audio_rate_hz=48000"
      "&device_output_latency_s=0.03";

  static web::ApiRequest post(const std::string& key, const std::string& body, const std::string& origin = "http://localhost") {
    web::ApiRequest r;
    r.method = "POST";
    r.path = "/api/answer";
    r.host = "localhost";
    r.origin = origin;
    r.passed_fields = {{web::kApiKeyField, key}};
    r.content_type = "application/x-www-form-urlencoded";
    r.body = body;
    return r;
  }
  static web::ApiRequest get(const std::string& path, const std::string& query, const std::string& key,
                             const std::string& method = "GET") {
    web::ApiRequest r;
    r.method = method;
    r.path = path;
    r.query = query;
    r.host = "localhost";
    r.passed_fields = {{web::kApiKeyField, key}};
    return r;
  }
  // The files of the results folder that name the participant.
  std::vector<std::string> files_of(const std::string& participant) const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) {
      const std::string name = e.path().filename().string();
      if (name.rfind(participant + ".", 0) == 0) names.push_back(name);
    }
    return names;
  }

  fs::path dir_;
  MatchingStudy study_;
  StudySecret secret_{};
};

TEST_F(StudyServiceTest, EveryRefusalAndTheStateLeaveAParticipantWithoutAnyFile) {
  web::StudyService api = service(study_);
  const auto refused = [&](const std::string& participant, const web::ApiRequest& request, int status) {
    EXPECT_EQ(api.handle(request).status, status) << participant;
    EXPECT_EQ(files_of(participant), std::vector<std::string>{}) << participant << " (HTTP " << status << ")";
  };
  EXPECT_EQ(api.handle(get("/api/state", "participant=s1", key("s1"))).status, 200);
  EXPECT_EQ(files_of("s1"), std::vector<std::string>{}) << "the state";
  refused("r1", post(key("r1"), good("r1", 2) + kDevice), 409);                             // not the next trial
  refused("r2", post(key("r2"), body("r2", 1, other_of_set("r2", 1), presented("r2", 1)) + kDevice), 400);  // not the plan's
  refused("r3", post(key("r3"), body("r3", 1, presented("r3", 1), "nosuchimage") + kDevice), 400);  // not of the set
  refused("r4", post(key("r4"), good("r4", 1) + "&extra=1"), 400);                           // malformed
  refused("r5", post(key("r6"), good("r5", 1) + kDevice), 403);                              // another's key
  refused("r6", post(key("r6"), good("r6", 1) + kDevice, "http://evil.example"), 403);       // another Origin
  refused("r7", post(key("r7"), good("r7", 1) + "&x=" + std::string(web::kMaxAnswerBodyBytes, 'a')), 413);
  refused("r8", get("/api/state", "participant=r8", key("r8"), "PUT"), 405);
  // The burst spent (on trials out of order, 409) until the bucket refuses: 429.
  int status = 409;
  for (int i = 0; i < 1000 && status == 409; ++i) status = api.handle(post(key("r9"), good("r9", 2) + kDevice)).status;
  EXPECT_EQ(status, 429);
  EXPECT_EQ(files_of("r9"), std::vector<std::string>{}) << "429";
  // A state request of a known participant, after the refusals: still nothing.
  EXPECT_EQ(api.handle(get("/api/state", "participant=r1", key("r1"))).status, 200);
  EXPECT_EQ(files_of("r1"), std::vector<std::string>{});
  EXPECT_EQ(files_of(""), std::vector<std::string>{}) << "nothing at all in the results folder";
}

TEST_F(StudyServiceTest, TheFirstAcceptedTrialMakesTheTrialFileAndThenTheDeviceRecord) {
  web::StudyService api = service(study_);
  EXPECT_EQ(api.handle(get("/api/state", "participant=p1", key("p1"))).status, 200);
  const web::ApiReply reply = api.handle(post(key("p1"), good("p1", 1) + kDevice));
  ASSERT_EQ(reply.status, 200) << reply.body;
  EXPECT_NE(reply.body.find("\"completed\": 1"), std::string::npos) << reply.body;
  EXPECT_EQ(files_of("p1"), (std::vector<std::string>{"p1.device.json", "p1.trials.csv"}));
  const std::string text = read_text(dir_ / "p1.trials.csv");
  EXPECT_EQ(text.substr(0, text.find('\n')), "participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc");
  const auto table = read_matching_trials(dir_ / "p1.trials.csv");
  ASSERT_TRUE(table.ok());
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.rows[0].trial, 1);
  EXPECT_EQ(table.rows[0].presented, presented("p1", 1));
  EXPECT_TRUE(table.rows[0].correct);
  // The second goes on in the same file.
  ASSERT_EQ(api.handle(post(key("p1"), good("p1", 2))).status, 200);
  EXPECT_EQ(read_matching_trials(dir_ / "p1.trials.csv").rows.size(), 2u);
}

TEST_F(StudyServiceTest, AFailedAppendLeavesNoDeviceRecordAndNoTrialFile) {
  // A row the log refuses (a set name with a comma; the study reader lets none through) stands in
  // for a disk that fails the write.
  MatchingStudy broken = study_;
  broken.sets[0].name = "complexity,broken";
  web::StudyService api = service(broken);
  const web::ApiReply reply = api.handle(post(key("p1"), good("p1", 1) + kDevice));
  EXPECT_EQ(reply.status, 500) << reply.body;
  EXPECT_EQ(files_of("p1"), std::vector<std::string>{});
}

TEST_F(StudyServiceTest, ATrialFileThatCannotBeOpenedIs503AndNothingIsWritten) {
  web::StudyService api = service(study_);
  // Held: another program (here this test, through its own TrialLog) writes the participant's log.
  TrialLogOptions options;
  options.total_trials = 40;
  auto held = TrialLog::open(dir_, "held", "trials", kMatchingTrialHeader, options);
  ASSERT_TRUE(std::holds_alternative<TrialLog>(held));
  const std::string before = read_text(dir_ / "held.trials.csv");
  EXPECT_EQ(api.handle(get("/api/state", "participant=held", key("held"))).status, 503);
  EXPECT_EQ(api.handle(post(key("held"), good("held", 1) + kDevice)).status, 503);
  EXPECT_EQ(read_text(dir_ / "held.trials.csv"), before);
  EXPECT_EQ(files_of("held"), std::vector<std::string>{"held.trials.csv"});
  // Released: the next answer is recorded.
  held = std::vector<Diagnostic>{};
  EXPECT_EQ(api.handle(post(key("held"), good("held", 1) + kDevice)).status, 200);
  EXPECT_EQ(files_of("held"), (std::vector<std::string>{"held.device.json", "held.trials.csv"}));

  // Not a file: a folder where the trial file would be.
  fs::create_directory(dir_ / "folder.trials.csv");
  EXPECT_EQ(api.handle(get("/api/state", "participant=folder", key("folder"))).status, 503);
  EXPECT_EQ(api.handle(post(key("folder"), good("folder", 1) + kDevice)).status, 503);
  EXPECT_EQ(files_of("folder"), std::vector<std::string>{"folder.trials.csv"});
  EXPECT_TRUE(fs::is_empty(dir_ / "folder.trials.csv"));
}

TEST_F(StudyServiceTest, StateAndLinkWithoutAParticipantAre400) {
  web::StudyService api = service(study_);
  for (const std::string query : {"", "participant=", "participant=a%2Fb", "participant=a/b", "who=p1", "participant=p1&participant=p2"}) {
    EXPECT_EQ(api.handle(get("/api/state", query, key("p1"))).status, 400) << "state?" << query;
    EXPECT_EQ(api.handle(get("/api/link", query, researcher_key())).status, 400) << "link?" << query;
  }
  EXPECT_EQ(api.handle(get("/api/link", "participant=p1", researcher_key())).status, 200);
  EXPECT_EQ(files_of(""), std::vector<std::string>{});
}

TEST_F(StudyServiceTest, OnlyGetAndHeadOrAnAnswersPostAreServed) {
  web::StudyService api = service(study_);
  for (const char* method : {"PUT", "DELETE", "PATCH", "OPTIONS", "POST"}) {
    for (const char* path : {"/api/state", "/api/progress", "/api/report", "/api/link"}) {
      web::ApiRequest r = get(path, "participant=p1", std::string(path) == "/api/state" ? key("p1") : researcher_key(), method);
      EXPECT_EQ(api.handle(r).status, 405) << method << " " << path;
    }
  }
  for (const char* method : {"GET", "HEAD", "PUT", "DELETE", "PATCH", "OPTIONS"}) {
    web::ApiRequest r = post(key("p1"), good("p1", 1));
    r.method = method;
    EXPECT_EQ(api.handle(r).status, 405) << method << " /api/answer";
  }
  EXPECT_EQ(api.handle(get("/api/state", "participant=p1", key("p1"), "HEAD")).status, 200);
  EXPECT_EQ(files_of(""), std::vector<std::string>{});
}

TEST_F(StudyServiceTest, TheBodysBoundHoldsOnBothSidesAndIsCheckedFirst) {
  web::StudyService api = service(study_);
  // A well-formed answer of exactly kMaxAnswerBodyBytes (path_mm written with trailing zeros).
  const std::string exact = answer_of_size(good("p1", 1), web::kMaxAnswerBodyBytes);
  const std::string one_more = answer_of_size(good("p1", 1), web::kMaxAnswerBodyBytes + 1);
  ASSERT_EQ(exact.size(), web::kMaxAnswerBodyBytes);
  ASSERT_EQ(one_more.size(), web::kMaxAnswerBodyBytes + 1);
  EXPECT_EQ(api.handle(post(key("p1"), one_more)).status, 413);
  EXPECT_EQ(files_of("p1"), std::vector<std::string>{});
  const web::ApiReply accepted = api.handle(post(key("p1"), exact));
  EXPECT_EQ(accepted.status, 200) << accepted.body;
  EXPECT_EQ(read_matching_trials(dir_ / "p1.trials.csv").rows.size(), 1u);
  // The documented order: the size before the Origin, the body before the key.
  const std::string next = good("p1", 2) + "&x=" + std::string(web::kMaxAnswerBodyBytes, 'a');
  EXPECT_EQ(api.handle(post(std::string(32, '0'), next)).status, 413) << "an oversized body with a wrong key";
  EXPECT_EQ(api.handle(post("", next, "")).status, 413) << "an oversized body without key or Origin";
  EXPECT_EQ(api.handle(post(std::string(32, '0'), "not a form", "")).status, 403) << "no Origin comes before the body";
  EXPECT_EQ(api.handle(post(std::string(32, '0'), "not a form")).status, 400) << "a malformed body before the key";
  EXPECT_EQ(api.handle(post(std::string(32, '0'), good("p1", 3))).status, 403) << "the key before the trial's order";
  EXPECT_EQ(read_matching_trials(dir_ / "p1.trials.csv").rows.size(), 1u);
}

TEST_F(StudyServiceTest, AnOriginIsThisServersHostOverHttpOrHttps) {
  web::StudyService api = service(study_);
  // https with the request's Host: the page behind a TLS proxy that passes Host (docs/web-study.md).
  EXPECT_EQ(api.handle(post(key("p1"), good("p1", 1), "https://localhost")).status, 200);
  for (const char* origin : {"https://localhost:8443", "http://localhost:80", "https://evil.example", "https://localhost.evil.example",
                             "ftp://localhost", "localhost", "null", "HTTPS://localhost"}) {
    EXPECT_EQ(api.handle(post(key("p1"), good("p1", 2), origin)).status, 403) << origin;
  }
  web::ApiRequest proxied = post(key("p1"), good("p1", 2), "https://study.example.org");
  proxied.host = "study.example.org";
  EXPECT_EQ(api.handle(proxied).status, 200);
  EXPECT_EQ(read_matching_trials(dir_ / "p1.trials.csv").rows.size(), 2u);
}

}  // namespace
}  // namespace vimg::test
