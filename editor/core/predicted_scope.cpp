#include "editor/core/predicted_scope.hpp"

#include <algorithm>

namespace vimg::editor {

void PredictedScope::set_response(const ResponseParams& params, std::uint64_t generation) {
  if (generation == generation_ && model_) return;
  params_ = params;
  generation_ = generation;
  model_.reset();  // designed again on the next update, at the tap's rate
}

void PredictedScope::restart() {
  std::fill(drive_.begin(), drive_.end(), 0.0f);
  std::fill(acceleration_.begin(), acceleration_.end(), 0.0f);
  head_ = 0;
  modelled_ = 0;
  skipped_ = 0;
}

void PredictedScope::update(const DriveTap& tap) {
  const double rate = tap.sample_rate_hz();
  if (!(rate > 0.0)) return;
  if (&tap != tap_ || rate != sample_rate_hz_) {
    tap_ = &tap;
    sample_rate_hz_ = rate;
    cursor_ = 0;
    model_.reset();
    restart();
  }
  if (!model_) model_.emplace(params_, sample_rate_hz_);
  std::uint64_t skipped = 0;
  cursor_ = tap.copy_since(cursor_, fresh_, &skipped);
  skipped_ += skipped;
  for (const float d : fresh_) {
    drive_[head_] = d;
    acceleration_[head_] = static_cast<float>(model_->process(d));
    head_ = (head_ + 1) % kHistory;
  }
  modelled_ += fresh_.size();
}

void PredictedScope::recent(std::size_t count, std::vector<float>& drive, std::vector<float>& acceleration) const {
  count = std::min(count, kHistory);
  drive.assign(count, 0.0f);
  acceleration.assign(count, 0.0f);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = (head_ + kHistory - count + i) % kHistory;
    drive[i] = drive_[at];
    acceleration[i] = acceleration_[at];
  }
}

}  // namespace vimg::editor
