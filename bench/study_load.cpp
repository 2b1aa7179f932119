// The study server under load beside hostile sockets (docs/benchmarks/study-server.md, "Study server under
// hostile sockets"): PARTICIPANTS simulated participants each answer TRIALS trials of the shipped
// matching example through the study API, one every PERIOD ms, with their keys, as the page does
// over one kept-alive connection each (answers delivered in order; 429, 503 and lost connections
// waited out 100 ms, doubling to 2 s).
// Meanwhile SILENT sockets say nothing and SLOW ones send a header byte every SLOW_PERIOD ms, all
// reopened when the server closes them, and the dashboard's progress is fetched once a second.
// Targets: every trial recorded exactly once with correct == (presented == chosen); answer round
// trip (the confirmed request) p99 <= 100 ms; no answer confirmed later than 2 s after it was first
// sent; every progress answered within 1 s. With --image, `vimg serve` of the smiley instead: a
// page's files and an event stream's greeting are fetched once a second, each within 1 s.
// The page's files are stand-ins (VIMG_WEB_ASSETS): the server is measured, not the page.
// usage: study_load VIMG SOURCE_DIR WORK_DIR [PARTICIPANTS TRIALS PERIOD_MS SILENT SLOW SLOW_PERIOD_MS] [--image]
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "bench/load/load_clients.hpp"
#include "storage/atomic_file.hpp"
#include "storage/read_file.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/trial_table.hpp"
#include "study/matching_row.hpp"
#include "study/trial_plan.hpp"
#include "web/study_server/study_keys.hpp"

namespace vimg::bench {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

constexpr milliseconds kReplyBound{10000};
constexpr std::chrono::seconds kRunBound{60};  // after the last answer is due: the run ends, counted
constexpr double kRoundTripP99Target_ms = 100, kDeliveryTarget_ms = 2000, kPollTarget_ms = 1000;

struct Settings {
  int participants = 20, trials = 40, period_ms = 100, silent = 200, slow = 100, slow_period_ms = 2000;
  bool image = false;
};

struct Figures {
  std::mutex mutex;
  std::vector<double> round_trip_ms, delivery_ms, poll_ms;
  int retried = 0, poll_failures = 0;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

std::string post_answer(const std::string& key, const std::string& body) {
  return "POST /api/answer HTTP/1.1\r\nHost: localhost\r\nOrigin: http://localhost\r\n"
         "Content-Type: application/x-www-form-urlencoded\r\nX-Vimg-Key: " + key + "\r\nContent-Length: " +
         std::to_string(body.size()) + "\r\n\r\n" + body;
}
std::string get(const std::string& target, const std::string& key = "") {
  return "GET " + target + " HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n" +
         (key.empty() ? "" : "X-Vimg-Key: " + key + "\r\n") + "\r\n";
}

// One participant, as the page delivers: each answer once it is due, in order, until confirmed.
void participate(int port, const std::string& id, const std::string& key, const std::vector<std::string>& presented,
                 const std::vector<std::vector<std::string>>& choices, const Settings& s, Clock::time_point start, Figures& f) {
  std::mt19937 random(static_cast<unsigned>(std::hash<std::string>{}(id)));
  KeepAliveClient connection(port);
  for (int k = 1; k <= s.trials; ++k) {
    std::this_thread::sleep_until(start + milliseconds(s.period_ms * (k - 1)));
    const auto& set = choices[static_cast<std::size_t>(k - 1)];
    const std::string chosen = set[random() % set.size()];
    const std::string body = "participant=" + id + "&trial=" + std::to_string(k) + "&presented=" +
                             presented[static_cast<std::size_t>(k - 1)] + "&chosen=" + chosen +
                             "&rub_s=1.5&response_s=0.25&path_mm=12.5";
    const auto first_sent = Clock::now();
    int wait_ms = 100, retries = 0;
    const auto give_up = start + milliseconds(s.period_ms * s.trials) + kRunBound;
    while (true) {
      if (Clock::now() > give_up) return;  // this participant is stuck: the answers missing are counted
      const auto sent = Clock::now();
      const Reply reply = connection.request(post_answer(key, body), kReplyBound);
      const std::size_t at = reply.body.find("\"completed\": ");
      const int completed = at == std::string::npos ? 0 : std::atoi(reply.body.c_str() + at + 13);
      if ((reply.status == 200 || reply.status == 409) && completed >= k) {
        const std::lock_guard lock(f.mutex);
        f.round_trip_ms.push_back(ms_since(sent));
        f.delivery_ms.push_back(ms_since(first_sent));
        f.retried += retries;
        break;
      }
      if (reply.status != 0 && reply.status != 429 && reply.status < 500) {
        std::printf("FAIL %s trial %d: HTTP %d %s", id.c_str(), k, reply.status, reply.body.c_str());
        return;
      }
      ++retries;
      std::this_thread::sleep_for(milliseconds(wait_ms));
      wait_ms = std::min(2000, wait_ms * 2);
    }
  }
}

// Every second until `done`: each of `targets` must be answered 200 within kPollTarget_ms (an
// event stream: its greeting).
void poll(int port, const std::vector<std::string>& targets, const std::string& key, const std::atomic<bool>& done, Figures& f) {
  while (!done) {
    const auto round = Clock::now();
    for (const std::string& target : targets) {
      const auto sent = Clock::now();
      const bool stream = target == "/events";
      const Reply reply = request(port, get(target, key), stream ? milliseconds(1000) : kReplyBound);
      const double ms = ms_since(sent);
      const bool ok = stream ? reply.body.find(": connected") != std::string::npos : reply.status == 200;
      const std::lock_guard lock(f.mutex);
      f.poll_ms.push_back(stream && ok ? 0.0 : ms);
      if (!ok || (!stream && ms > kPollTarget_ms)) ++f.poll_failures;
    }
    std::this_thread::sleep_until(round + milliseconds(1000));
  }
}

// The port of the URL `vimg serve` printed ("...:PORT/... (Ctrl-C stops)"), 0 if none within 60 s.
int wait_for_port(const ServeChild& serve, std::string& printed) {
  for (const auto give_up = Clock::now() + std::chrono::seconds(60); Clock::now() < give_up;) {
    printed = read_regular_file(serve.out_file(), 1 << 20).bytes.value_or("");
    const std::size_t line_end = printed.find(" (Ctrl-C stops)");
    if (line_end != std::string::npos) {
      const std::size_t scheme = printed.rfind("http://127.0.0.1:", line_end);
      if (scheme != std::string::npos) return std::atoi(printed.c_str() + scheme + 17);
    }
    std::this_thread::sleep_for(milliseconds(20));
  }
  return 0;
}

int run(const std::string& vimg, const fs::path& source, const fs::path& work, const Settings& s) {
  fs::remove_all(work);
  fs::create_directories(work / "assets");
  fs::create_directories(work / "results");
  for (const char* name : {"index.html", "vimg.js", "vimg.wasm", "worklet.js", "audio_clock.js", "study.html", "study.js",
                           "study_answers.js", "study_audio.js", "study_screens.js", "study_touch.js", "picture.js",
                           "dashboard.html"}) {
    write_file_atomically(work / "assets" / name, std::string("stand-in ") + name + "\n");
  }
  const fs::path study_file = source / "assets/examples/matching/study.xml";
  const std::vector<std::string> args = s.image ? std::vector<std::string>{(source / "assets/examples/smiley.vimg").string()}
                                                : std::vector<std::string>{"--study", study_file.string(), "--results", (work / "results").string()};
  ServeChild serve(vimg, args, work.string(), (work / "assets").string());
  std::string printed;
  const int port = wait_for_port(serve, printed);
  if (port == 0) {
    std::printf("FAIL: vimg serve printed no URL:\n%s\n", printed.c_str());
    return 1;
  }
  HostileClients hostile(port, s.silent, s.slow, milliseconds(s.slow_period_ms));
  for (const auto give_up = Clock::now() + std::chrono::seconds(10); hostile.open_now() < s.silent + s.slow && Clock::now() < give_up;) {
    std::this_thread::sleep_for(milliseconds(10));
  }
  Figures f;
  std::atomic<bool> done{false};
  int failed = 0;
  if (s.image) {
    std::thread poller([&] { poll(port, {"/", "/vimg.js", "/images/index.json", "/events"}, "", done, f); });
    std::this_thread::sleep_for(milliseconds(s.trials * s.period_ms));
    done = true;
    poller.join();
  } else {
    const std::size_t at = printed.find("#key=");
    const std::string researcher = at == std::string::npos ? "" : printed.substr(at + 5, 32);
    auto loaded = load_matching_study(study_file);
    const auto keys = web::StudyKeys::open(work / "results");
    const auto stems = study::matching_study_stems(*loaded.study);
    std::vector<std::thread> threads;
    const auto start = Clock::now() + milliseconds(200);
    std::thread poller([&] { poll(port, {"/api/progress"}, researcher, done, f); });
    for (int p = 0; p < s.participants; ++p) {
      const std::string id = "load" + std::to_string(p);
      std::vector<std::string> presented;
      std::vector<std::vector<std::string>> choices;
      for (const auto& trial : study::plan_matching_trials(*loaded.study, id)) {
        presented.push_back(stems[trial.set][trial.image]);
        choices.push_back(stems[trial.set]);
      }
      const std::string key = std::get<web::StudyKeys>(keys).participant_key(id);
      threads.emplace_back([=, &s, &f] { participate(port, id, key, presented, choices, s, start, f); });
    }
    for (std::thread& t : threads) t.join();
    done = true;
    poller.join();
    for (int p = 0; p < s.participants; ++p) {
      const std::string id = "load" + std::to_string(p);
      const auto table = read_matching_trials(work / "results" / (id + ".trials.csv"));
      bool exact = static_cast<int>(table.rows.size()) == s.trials;
      for (std::size_t i = 0; exact && i < table.rows.size(); ++i) {
        const MatchingTrial& row = table.rows[i];
        exact = row.trial == static_cast<int>(i) + 1 && row.correct == (row.presented == row.chosen);
      }
      if (!exact) {
        std::printf("FAIL %s: %zu rows, not trials 1..%d once with correct == (presented == chosen)\n", id.c_str(),
                    table.rows.size(), s.trials);
        ++failed;
      }
    }
    const std::size_t answers = f.round_trip_ms.size();
    std::printf("%d participants x %d trials every %d ms, %d silent + %d slow sockets (reopened %d times): %zu answers "
                "confirmed (%d retries); round trip p50 %.1f ms, p99 %.1f ms, max %.1f ms; delivery max %.0f ms\n",
                s.participants, s.trials, s.period_ms, s.silent, s.slow, hostile.reopened(), answers, f.retried,
                quantile(f.round_trip_ms, 0.5), quantile(f.round_trip_ms, 0.99), quantile(f.round_trip_ms, 1.0),
                quantile(f.delivery_ms, 1.0));
    if (answers != static_cast<std::size_t>(s.participants * s.trials)) ++failed;
    if (quantile(f.round_trip_ms, 0.99) > kRoundTripP99Target_ms) std::printf("FAIL: round trip p99 over 100 ms\n"), ++failed;
    if (quantile(f.delivery_ms, 1.0) > kDeliveryTarget_ms) std::printf("FAIL: an answer delivered over 2 s after it was sent\n"), ++failed;
  }
  std::printf("%s polled %zu times: max %.0f ms, %d not answered within 1 s\n", s.image ? "page files and /events" : "progress",
              f.poll_ms.size(), quantile(f.poll_ms, 1.0), f.poll_failures);
  if (f.poll_failures > 0 || f.poll_ms.empty()) ++failed;
  std::printf("%s\n", failed ? "FAILED" : "all targets met");
  return failed ? 1 : 0;
}

}  // namespace
}  // namespace vimg::bench

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  vimg::bench::Settings s;
  s.image = std::erase(args, "--image") > 0;
  if (args.size() < 3) {
    std::fprintf(stderr, "usage: study_load VIMG SOURCE_DIR WORK_DIR [PARTICIPANTS TRIALS PERIOD_MS SILENT SLOW SLOW_PERIOD_MS] [--image]\n");
    return 2;
  }
  int* fields[] = {&s.participants, &s.trials, &s.period_ms, &s.silent, &s.slow, &s.slow_period_ms};
  for (std::size_t i = 3; i < args.size() && i - 3 < 6; ++i) *fields[i - 3] = std::atoi(args[i].c_str());
  return vimg::bench::run(args[0], args[1], args[2], s);
}
