#include "web/study_server/participant_logs.hpp"

#include <algorithm>
#include <variant>

#include "storage/study/trial_table.hpp"

namespace vimg::web {

bool RateBucket::take(double now_s) {
  if (last_s_) tokens_ = std::min(capacity_, tokens_ + (now_s - *last_s_) * rate_per_s_);
  last_s_ = now_s;
  if (tokens_ < 1.0) return false;
  tokens_ -= 1.0;
  return true;
}

std::size_t ParticipantEntry::completed() const { return log ? log->completed() : 0; }

void ParticipantLogs::open(const std::string& participant, ParticipantEntry& entry) const {
  TrialLogOptions options;
  options.total_trials = total_;
  auto opened = TrialLog::open(dir_, participant, "trials", kMatchingTrialHeader, options);
  if (auto* log = std::get_if<TrialLog>(&opened)) {
    entry.log = std::move(*log);
    return;
  }
  // Refused: a finished participant, or a file that is broken or held by another program.
  const std::filesystem::path file = dir_ / (participant + ".trials.csv");
  const auto table = read_matching_trials(file);
  if (table.ok() && table.rows.size() == total_) {
    entry.finished = true;
    return;
  }
  for (const Diagnostic& d : std::get<std::vector<Diagnostic>>(opened)) {
    if (!entry.error.empty()) entry.error += "\n";
    entry.error += d.to_string();
  }
}

void ParticipantLogs::with(const std::string& participant, const std::function<void(ParticipantEntry&)>& use) {
  Slot* slot = nullptr;
  {
    const std::lock_guard<std::mutex> lock(map_mutex_);
    auto& owned = slots_[participant];
    if (!owned) owned = std::make_unique<Slot>();
    slot = owned.get();
  }
  const std::lock_guard<std::mutex> lock(slot->mutex);
  // A log that could not be opened (held by vimg-player, say) is tried again on the next request.
  if (!slot->entry.log && !slot->entry.finished) {
    slot->entry.error.clear();
    open(participant, slot->entry);
  }
  use(slot->entry);
}

}  // namespace vimg::web
