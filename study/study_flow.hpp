#pragma once
// The matching test's procedure (docs/player.md, "Matching test"), apart from drawing and devices:
// which screen is up, which trial runs, and what a trial measured; the one state machine of
// vimg-player and of the study page in the browser (compiled to WebAssembly,
// web/wasm/study_exports.cpp; docs/studies.md). Pure: every call takes the time
// (`now_s`, seconds on any monotonic clock, the same one as the touch events' time_s), so tests
// drive it with a fake clock and the scripted mode with the gesture's own times.
//
//   welcome --tap--> [training of the set --countdown or skip-->] rubbing --Answer--> answering
//   answering --tap on a picture--> (row recorded) rubbing of the next trial
//                                    | pause (the next trial is in another set) --tap--> training ...
//                                    | end (that was the last trial)
//
// Training runs for a set whose first trial is the next one: a run that resumes inside a set
// (after a crash or Esc) goes straight on with that set's trials; one that resumes at a set's first
// trial trains on it first.
// Threads: one (the UI thread).
#include <cstddef>
#include <optional>
#include <vector>

#include "player/touch_event.hpp"
#include "study/trial_plan.hpp"

namespace vimg::study {

enum class StudyScreen { welcome, training, rubbing, answering, pause, end };

struct StudyFlowOptions {
  double training_s = 180.0;  // per set; 0: no training
  bool welcome = true;        // a first screen the experimenter taps away (the live run)
};

// What one trial measured; the caller adds names, the participant and the time and appends it.
struct StudyTrialResult {
  std::size_t trial = 0;  // 1-based across the whole study
  std::size_t set = 0;
  std::size_t presented = 0;  // image index within the set
  std::size_t chosen = 0;
  double rub_s = 0.0;       // first touch of the trial to Answer
  double response_s = 0.0;  // Answer to the tap on a picture
  double path_mm = 0.0;     // every finger's path while rubbing, summed
};

class StudyFlow {
 public:
  // `images_per_set[s]`: how many pictures set s has (>= 1). `plan`: trial k is plan[k - 1].
  // `completed`: trials already recorded; the flow begins at trial completed + 1.
  StudyFlow(std::vector<std::size_t> images_per_set, std::vector<MatchingTrialPlan> plan,
            std::size_t completed, StudyFlowOptions options, double now_s);

  StudyScreen screen() const { return screen_; }
  std::size_t total_trials() const { return plan_.size(); }
  // The trial under way or next (1-based); total_trials() + 1 at the end.
  std::size_t trial() const { return next_ + 1; }
  // The set of that trial (the last set at the end).
  std::size_t set() const;
  std::size_t set_count() const { return images_per_set_.size(); }
  std::size_t images_in_set() const { return images_per_set_[set()]; }
  // The picture presented in the trial under way (rubbing, answering).
  std::size_t presented() const { return plan_[next_].image; }

  // welcome -> training of the set, or its next trial. Ignored elsewhere.
  void begin(double now_s);
  // The training countdown; called every frame.
  void tick(double now_s);
  double training_left_s(double now_s) const;
  // The experimenter ends training early. Ignored elsewhere.
  void skip_training(double now_s);
  // Which of the set's pictures the training screen shows and plays (a tap on its thumbnail).
  void show_training_picture(std::size_t image);
  std::size_t training_picture() const { return training_picture_; }

  // A touch on the rubbing screen (outside the Answer button): the trial's first touch starts
  // rub_s; moves add to the path. Ignored on other screens.
  void touch(const TouchEvent& event);
  // Answer is offered once the participant has touched the screen in this trial.
  bool can_answer() const { return screen_ == StudyScreen::rubbing && touched_; }
  // rubbing -> answering; false (nothing changes) unless can_answer().
  bool answer(double now_s);
  // The participant taps picture `image` of the set: the trial's result, and the flow moves to the
  // next trial, the pause or the end. Nullopt (nothing changes) when not answering or no such image.
  std::optional<StudyTrialResult> choose(std::size_t image, double now_s);
  // pause -> training of the next set (or its first trial). Ignored elsewhere.
  void resume(double now_s);

 private:
  void enter_trial_or_training(double now_s);
  void start_rubbing();
  struct FingerTrack {
    int finger = 0;
    double x_mm = 0.0, y_mm = 0.0;
  };

  std::vector<std::size_t> images_per_set_;
  std::vector<MatchingTrialPlan> plan_;
  StudyFlowOptions options_;
  std::size_t next_ = 0;  // 0-based index of the trial under way or next
  StudyScreen screen_ = StudyScreen::welcome;
  double training_end_s_ = 0.0;
  std::size_t training_picture_ = 0;
  bool touched_ = false;
  double first_touch_s_ = 0.0;
  double answer_s_ = 0.0;
  double rub_s_ = 0.0;
  double path_mm_ = 0.0;
  std::vector<FingerTrack> fingers_;  // fingers down now, with their last position
};

}  // namespace vimg::player_app
