#pragma once
// The trial logs of the participants a study server has seen (web/study_server/study_service.hpp):
// each participant's DIR/ID.trials.csv through the one TrialLog (storage/study/trial_log.hpp). A
// file that exists is opened on the first request with that participant's key and held open
// (locked against a second writer) until the server stops; a file that does not exist is made only
// by the participant's first accepted trial (create()), so that a request that is refused, or only
// asks for the state, leaves no file behind. One mutex per participant: answers of different
// participants are written in parallel, answers of one participant one after the other. A finished
// participant's log cannot be opened (TrialLog refuses it); the file is then read to tell
// "finished" from a broken file. Each participant also has the bucket that rate-limits their
// answers (kAnswerBurst at once, kAnswersPerSecond after that).
// Threads: any; every call locks what it touches.
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "storage/study/trial_log.hpp"

namespace vimg::web {

inline constexpr double kAnswerBurst = 20.0;
inline constexpr double kAnswersPerSecond = 4.0;

// A token bucket: `capacity` requests at once, refilled at `rate_per_s`. Pure (the caller gives
// the time).
class RateBucket {
 public:
  RateBucket(double capacity, double rate_per_s) : capacity_(capacity), rate_per_s_(rate_per_s), tokens_(capacity) {}
  bool take(double now_s);

 private:
  double capacity_, rate_per_s_, tokens_;
  std::optional<double> last_s_;
};

struct ParticipantEntry {
  std::optional<TrialLog> log;  // open unless finished, broken or not made yet (no trial accepted)
  bool finished = false;
  std::string error;            // the log could not be opened (it is not finished): why
  std::size_t completed() const;
};

class ParticipantLogs {
 public:
  ParticipantLogs(std::filesystem::path dir, std::size_t total_trials) : dir_(std::move(dir)), total_(total_trials) {}

  // Takes one answer from the participant's bucket; false when it is empty (429). Checked before
  // anything waits: it never takes the participant's lock, which an answer being synced holds.
  bool take_answer(const std::string& participant, double now_s);

  // Runs `use` with the participant's entry locked, its log opened first if it is not yet.
  void with(const std::string& participant, const std::function<void(ParticipantEntry&)>& use);

  // Appends the participant's accepted row (called inside with()): the log is made first when the
  // file does not exist yet, and removed again when that first row cannot be appended, so a
  // failure leaves no file. The error, or nothing.
  std::optional<std::string> append(const std::string& participant, ParticipantEntry& entry,
                                    const std::vector<std::string>& cells) const;

  // The trial files held open now: they share the server's descriptors with its connections
  // (web/server/descriptor_budget.hpp). Never waits.
  int open_logs() const { return open_logs_.load(); }

 private:
  struct Slot {
    std::mutex mutex;
    ParticipantEntry entry;
    RateBucket answers{kAnswerBurst, kAnswersPerSecond};  // under map_mutex_, not `mutex`
  };
  Slot& slot_of(const std::string& participant);  // with map_mutex_ held
  void open(const std::string& participant, ParticipantEntry& entry) const;
  std::variant<TrialLog, std::vector<Diagnostic>> open_log(const std::string& participant) const;
  std::filesystem::path dir_;
  std::size_t total_;
  mutable std::atomic<int> open_logs_{0};
  std::mutex map_mutex_;
  std::map<std::string, std::unique_ptr<Slot>> slots_;
};

}  // namespace vimg::web
