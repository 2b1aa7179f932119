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

namespace {

std::filesystem::path trial_file(const std::filesystem::path& dir, const std::string& participant) {
  return dir / (participant + ".trials.csv");
}

bool something_at(const std::filesystem::path& file) {
  std::error_code ec;
  return std::filesystem::symlink_status(file, ec).type() != std::filesystem::file_type::not_found;
}

}  // namespace

std::variant<TrialLog, std::vector<Diagnostic>> ParticipantLogs::open_log(const std::string& participant) const {
  TrialLogOptions options;
  options.total_trials = total_;
  return TrialLog::open(dir_, participant, "trials", kMatchingTrialHeader, options);
}

void ParticipantLogs::open(const std::string& participant, ParticipantEntry& entry) const {
  const std::filesystem::path file = trial_file(dir_, participant);
  if (!exists(file)) return;  // made by the first accepted trial (append)
  auto opened = open_log(participant);
  if (auto* log = std::get_if<TrialLog>(&opened)) {
    entry.log = std::move(*log);
    ++open_logs_;
    return;
  }
  // Refused: a finished participant, or a file that is broken or held by another program.
  const auto table = read_matching_trials(file);
  if (table.ok() && table.rows.size() == total_) {
    entry.finished = true;
    return;
  }
  entry.error = join_diagnostics(std::get<std::vector<Diagnostic>>(opened));
}

std::optional<std::string> ParticipantLogs::append(const std::string& participant, ParticipantEntry& entry,
                                                   const std::vector<std::string>& cells) const {
  const bool made_here = !entry.log && !something_at(trial_file(dir_, participant));
  if (!entry.log) {
    auto opened = open_log(participant);
    if (auto* problems = std::get_if<std::vector<Diagnostic>>(&opened)) return join_diagnostics(*problems);
    entry.log = std::move(std::get<TrialLog>(opened));
    ++open_logs_;
  }
  const auto error = entry.log->append(cells);
  if (error && made_here && entry.log->completed() == 0) {
    // The file this request made holds only its header: it goes again, as if never made.
    const std::filesystem::path file = entry.log->path();
    entry.log.reset();
    --open_logs_;
    std::error_code ec;
    std::filesystem::remove(file, ec);
  }
  return error;
}

ParticipantLogs::Slot& ParticipantLogs::slot_of(const std::string& participant) {
  auto& owned = slots_[participant];
  if (!owned) owned = std::make_unique<Slot>();
  return *owned;
}

bool ParticipantLogs::take_answer(const std::string& participant, double now_s) {
  const std::lock_guard<std::mutex> lock(map_mutex_);
  return slot_of(participant).answers.take(now_s);
}

void ParticipantLogs::with(const std::string& participant, const std::function<void(ParticipantEntry&)>& use) {
  Slot* slot = nullptr;
  {
    const std::lock_guard<std::mutex> lock(map_mutex_);
    slot = &slot_of(participant);
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
