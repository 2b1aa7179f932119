// `vimg serve --study` across restarts and for the researcher: links stay valid after the server
// is killed and started again, the participant resumes at the next unanswered trial and every
// trial is in the file exactly once; a finished participant is refused; the dashboard's progress
// and report (the report is `vimg study report`'s HTML of the same files); `vimg study link`.
#include <signal.h>

#include <gtest/gtest.h>

#include <string>

#include "storage/study/trial_log.hpp"
#include "storage/study/trial_table.hpp"
#include "tests/study_server/study_fixture.hpp"

namespace vimg::test {
namespace {

TEST_F(StudyServer, AKilledServerRestartsWithTheSameLinksAndResumesAtTheNextTrial) {
  const std::string key = participant_key("p1");  // made before the server ever ran
  start();
  for (std::size_t trial = 1; trial <= 5; ++trial) ASSERT_EQ(post("/api/answer", key, good_answer("p1", trial)).status, 200);
  EXPECT_EQ(serve_->stop_with(SIGKILL), -1);
  start();
  EXPECT_EQ(participant_key("p1"), key);
  const HttpResponse state = get("/api/state?participant=p1", key);
  ASSERT_EQ(state.status, 200) << state.body;
  EXPECT_NE(state.body.find("\"completed\": 5"), std::string::npos) << state.body;
  // The page resends trial 5 (its confirmation was lost): refused, the row is there once.
  const HttpResponse again = post("/api/answer", key, good_answer("p1", 5));
  EXPECT_EQ(again.status, 409);
  EXPECT_NE(again.body.find("\"completed\": 5"), std::string::npos) << again.body;
  ASSERT_EQ(post("/api/answer", key, good_answer("p1", 6)).status, 200);
  const auto table = read_matching_trials(trial_file("p1"));
  ASSERT_TRUE(table.ok());
  ASSERT_EQ(table.rows.size(), 6u);
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    EXPECT_EQ(table.rows[i].trial, static_cast<int>(i + 1));
    EXPECT_EQ(table.rows[i].presented, presented("p1", i + 1));
  }
}

TEST_F(StudyServer, AFinishedParticipantIsRefused) {
  // All 40 trials written as vimg-player would have.
  {
    TrialLogOptions options;
    options.total_trials = 40;
    auto opened = TrialLog::open(results(), "done", "trials", kMatchingTrialHeader, options);
    ASSERT_TRUE(std::holds_alternative<TrialLog>(opened));
    TrialLog& log = std::get<TrialLog>(opened);
    const auto plan = study::plan_matching_trials(study_, "done");
    for (std::size_t k = 1; k <= plan.size(); ++k) {
      const study::StudyTrialResult r{k, plan[k - 1].set, plan[k - 1].image, plan[k - 1].image, 1.0, 0.5, 10.0};
      ASSERT_FALSE(log.append(to_cells(study::matching_trial_row(study_, stems_, "done", r, "2026-11-27T00:00:00Z"))));
    }
  }
  start();
  const std::string key = participant_key("done");
  const HttpResponse state = get("/api/state?participant=done", key);
  ASSERT_EQ(state.status, 200);
  EXPECT_NE(state.body.find("\"finished\": 1"), std::string::npos) << state.body;
  EXPECT_NE(state.body.find("\"completed\": 40"), std::string::npos) << state.body;
  const std::string before = read_text(trial_file("done"));
  EXPECT_EQ(post("/api/answer", key, good_answer("done", 40)).status, 409);
  EXPECT_EQ(read_text(trial_file("done")), before);
}

TEST_F(StudyServer, TheDashboardShowsProgressAndTheReportOfVimgStudyReport) {
  start();
  const std::string researcher = researcher_key();
  ASSERT_EQ(researcher.size(), 32u) << serve_->printed();
  EXPECT_EQ(get("/api/report", researcher).status, 404);  // no trials yet
  for (const char* p : {"b2", "a1"}) {
    const std::string key = participant_key(p);
    for (std::size_t trial = 1; trial <= 3; ++trial) ASSERT_EQ(post("/api/answer", key, good_answer(p, trial)).status, 200);
  }
  const HttpResponse progress = get("/api/progress", researcher);
  ASSERT_EQ(progress.status, 200);
  const std::size_t a1 = progress.body.find("\"participant\": \"a1\"");
  ASSERT_NE(a1, std::string::npos) << progress.body;
  EXPECT_EQ(progress.body.find("\"completed\": 3", a1), progress.body.find("\"completed\": ", a1)) << progress.body;
  EXPECT_NE(progress.body.find("\"participant\": \"b2\""), std::string::npos) << progress.body;

  const HttpResponse report = get("/api/report", researcher);
  ASSERT_EQ(report.status, 200) << report.body;
  EXPECT_EQ(report.headers.at("content-type"), "text/html; charset=utf-8");
  const CommandRun run = run_command(kVimg + " study report '" + trial_file("a1").string() + "' '" +
                                     trial_file("b2").string() + "' --out '" + (dir_ / "report.html").string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_EQ(report.body, read_text(dir_ / "report.html"));

  // The dashboard's links carry the key `vimg study link` prints.
  const HttpResponse link = get("/api/link?participant=c3", researcher);
  ASSERT_EQ(link.status, 200);
  EXPECT_NE(link.body.find("\"key\": \"" + participant_key("c3") + "\""), std::string::npos) << link.body;
}

TEST_F(StudyServer, StudyLinkPrintsTheServedAddressOrTheGivenOne) {
  start();
  CommandRun run = run_command(kVimg + " study link '" + results().string() + "' --participant demo");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_EQ(run.out, "http://127.0.0.1:" + std::to_string(port_) + "/study.html#participant=demo&key=" +
                         participant_key("demo") + "\n");
  // SIGTERM: exit 143, the temporary site removed (TMPDIR is the test's tmp folder).
  EXPECT_EQ(serve_->stop_with(SIGTERM), 143);
  EXPECT_TRUE(std::filesystem::is_empty(dir_ / "tmp"));
  run = run_command(kVimg + " study link '" + results().string() + "' --participant demo --url https://study.example.org");
  EXPECT_EQ(run.out, "https://study.example.org/study.html#participant=demo&key=" + participant_key("demo") + "\n");
  EXPECT_EQ(run_command(kVimg + " study link '" + results().string() + "' --participant 'a/b'").exit_code, 2);
  EXPECT_EQ(run_command(kVimg + " study link '" + results().string() + "' --participant a --url ftp://x/").exit_code, 2);
  // Usage errors of the server.
  EXPECT_EQ(run_command(kVimg + " serve --study '" + kExampleStudy.string() + "'").exit_code, 2);
  EXPECT_EQ(run_command(kVimg + " serve --results '" + results().string() + "'").exit_code, 2);
  EXPECT_EQ(run_command(kVimg + " serve x.vimg --study '" + kExampleStudy.string() + "' --results '" + results().string() +
                        "'").exit_code, 2);
  EXPECT_EQ(run_command(kVimg + " serve --study '" + kExampleStudy.string() + "' --results '" + (dir_ / "none").string() +
                        "' --port 0").exit_code, 1);
}

}  // namespace
}  // namespace vimg::test

namespace vimg::test {
namespace {

// --tls: HTTPS with the given certificate (a self-signed one made here with the openssl command),
// the study API behind it as over HTTP (an answer from https://HOST recorded, from another site refused); plain HTTP on that port gets no answer; a certificate that
// cannot be read stops the server with exit 1.
TEST_F(StudyServer, TlsServesTheStudyOverHttps) {
  const std::string cert = (dir_ / "cert.pem").string(), key = (dir_ / "key.pem").string();
  const CommandRun made = run_command("openssl req -x509 -newkey rsa:2048 -nodes -days 2 -subj /CN=127.0.0.1 -keyout '" + key +
                                      "' -out '" + cert + "'");
  ASSERT_EQ(made.exit_code, 0) << made.out;
  ServeProcess serve({"--study", kExampleStudy.string(), "--results", results().string(), "--tls", cert, key},
                     dir_ / "assets", dir_ / "tmp");
  const int port = serve.wait_for_port("https");
  ASSERT_GT(port, 0) << serve.printed();
  const std::string url = "https://127.0.0.1:" + std::to_string(port);
  const CommandRun state = run_command("curl -sk --max-time 30 -H 'X-Vimg-Key: " + participant_key("p1") + "' '" + url +
                                       "/api/state?participant=p1'");
  EXPECT_NE(state.out.find("\"trials\": 40"), std::string::npos) << state.out;
  const CommandRun wrong = run_command("curl -sk --max-time 30 -o /dev/null -w '%{http_code}' '" + url +
                                       "/api/state?participant=p1'");
  EXPECT_EQ(wrong.out, "403");
  // The page's answer carries Origin https://HOST (curl sends Host 127.0.0.1:PORT); another site's is refused.
  const auto answer_status = [&](const std::string& origin) {
    return run_command("curl -sk --max-time 30 -o /dev/null -w '%{http_code}' -H 'X-Vimg-Key: " + participant_key("p1") +
                       "' -H 'Origin: " + origin + "' --data '" + good_answer("p1", 1) + "' '" + url + "/api/answer'")
        .out;
  };
  EXPECT_EQ(answer_status("https://evil.example"), "403");
  EXPECT_FALSE(std::filesystem::exists(trial_file("p1")));
  EXPECT_EQ(answer_status(url), "200");
  EXPECT_EQ(read_matching_trials(trial_file("p1")).rows.size(), 1u);
  EXPECT_EQ(exchange(port, "GET", "/study.html").status, 0);  // plain HTTP: no HTTP answer
  EXPECT_EQ(run_command(kVimg + " serve --study '" + kExampleStudy.string() + "' --results '" + results().string() +
                        "' --port 0 --tls '" + (dir_ / "none.pem").string() + "' '" + key + "'").exit_code, 1);
}

}  // namespace
}  // namespace vimg::test
