#include "study/study_flow.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace vimg::study {

StudyFlow::StudyFlow(std::vector<std::size_t> images_per_set, std::vector<MatchingTrialPlan> plan,
                     std::size_t completed, StudyFlowOptions options, double now_s)
    : images_per_set_(std::move(images_per_set)), plan_(std::move(plan)), options_(options) {
  if (images_per_set_.empty()) throw std::invalid_argument("a study needs at least one set");
  for (const auto& trial : plan_) {
    if (trial.set >= images_per_set_.size() || trial.image >= images_per_set_[trial.set]) {
      throw std::invalid_argument("the trial plan names an image the study does not have");
    }
  }
  next_ = std::min(completed, plan_.size());
  if (next_ == plan_.size()) {
    screen_ = StudyScreen::end;
  } else if (options_.welcome) {
    screen_ = StudyScreen::welcome;
  } else {
    enter_trial_or_training(now_s);
  }
}

std::size_t StudyFlow::set() const {
  if (plan_.empty()) return 0;
  return plan_[std::min(next_, plan_.size() - 1)].set;
}

void StudyFlow::enter_trial_or_training(double now_s) {
  const bool first_of_set = next_ == 0 || plan_[next_ - 1].set != plan_[next_].set;
  if (first_of_set && options_.training_s > 0.0) {
    screen_ = StudyScreen::training;
    training_end_s_ = now_s + options_.training_s;
    training_picture_ = 0;
    return;
  }
  start_rubbing();
}

void StudyFlow::start_rubbing() {
  screen_ = StudyScreen::rubbing;
  touched_ = false;
  first_touch_s_ = answer_s_ = rub_s_ = path_mm_ = 0.0;
  fingers_.clear();
}

void StudyFlow::begin(double now_s) {
  if (screen_ == StudyScreen::welcome) enter_trial_or_training(now_s);
}

void StudyFlow::tick(double now_s) {
  if (screen_ == StudyScreen::training && now_s >= training_end_s_) start_rubbing();
}

double StudyFlow::training_left_s(double now_s) const {
  return screen_ == StudyScreen::training ? std::max(0.0, training_end_s_ - now_s) : 0.0;
}

void StudyFlow::skip_training(double) {
  if (screen_ == StudyScreen::training) start_rubbing();
}

void StudyFlow::show_training_picture(std::size_t image) {
  if (screen_ == StudyScreen::training && image < images_in_set()) training_picture_ = image;
}

void StudyFlow::touch(const TouchEvent& event) {
  if (screen_ != StudyScreen::rubbing) return;
  if (!touched_) {
    touched_ = true;
    first_touch_s_ = event.time_s;
  }
  auto track = std::find_if(fingers_.begin(), fingers_.end(), [&](const FingerTrack& f) { return f.finger == event.finger; });
  if (track != fingers_.end() && event.phase != TouchPhase::down) {
    path_mm_ += std::hypot(event.x_mm - track->x_mm, event.y_mm - track->y_mm);
  }
  if (event.phase == TouchPhase::up) {
    if (track != fingers_.end()) fingers_.erase(track);
    return;
  }
  // A move from a finger not seen going down (it was down before the trial began) starts its path.
  if (track == fingers_.end()) {
    fingers_.push_back({event.finger, event.x_mm, event.y_mm});
  } else {
    track->x_mm = event.x_mm;
    track->y_mm = event.y_mm;
  }
}

bool StudyFlow::answer(double now_s) {
  if (!can_answer()) return false;
  screen_ = StudyScreen::answering;
  answer_s_ = now_s;
  rub_s_ = std::max(0.0, now_s - first_touch_s_);
  fingers_.clear();
  return true;
}

std::optional<StudyTrialResult> StudyFlow::choose(std::size_t image, double now_s) {
  if (screen_ != StudyScreen::answering || image >= images_in_set()) return std::nullopt;
  StudyTrialResult result;
  result.trial = next_ + 1;
  result.set = plan_[next_].set;
  result.presented = plan_[next_].image;
  result.chosen = image;
  result.rub_s = rub_s_;
  result.response_s = std::max(0.0, now_s - answer_s_);
  result.path_mm = path_mm_;
  ++next_;
  if (next_ == plan_.size()) {
    screen_ = StudyScreen::end;
  } else if (plan_[next_].set != result.set) {
    screen_ = StudyScreen::pause;
  } else {
    start_rubbing();
  }
  return result;
}

void StudyFlow::resume(double now_s) {
  if (screen_ == StudyScreen::pause) enter_trial_or_training(now_s);
}

}  // namespace vimg::player_app
