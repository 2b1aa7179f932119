// The matching test's procedure for the study page (web/site/study.js): the one StudyFlow
// (study/study_flow.hpp) of vimg-player, driven through C functions. One flow per instance;
// every call takes the time (seconds, the page's performance.now() / 1000).
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "study/study_flow.hpp"

namespace {

std::unique_ptr<vimg::study::StudyFlow>& flow() {
  static std::unique_ptr<vimg::study::StudyFlow> f;
  return f;
}
vimg::study::StudyTrialResult& last_result() {
  static vimg::study::StudyTrialResult r;
  return r;
}

}  // namespace

extern "C" {

// `images_per_set[s]` for s < sets; `plan` holds trials pairs (set, image); `completed` trials are
// recorded already. training_s 0 skips training; welcome 1 starts on the welcome screen.
// 1, or 0 when the plan names an image the sets do not have (nothing is made).
int vimg_study_start(const int* images_per_set, int sets, const int* plan, int trials, int completed, double training_s,
                     int welcome, double now_s) {
  std::vector<std::size_t> counts;
  for (int s = 0; s < sets; ++s) counts.push_back(static_cast<std::size_t>(images_per_set[s] < 0 ? 0 : images_per_set[s]));
  std::vector<vimg::study::MatchingTrialPlan> trial_plan;
  for (int k = 0; k < trials; ++k) {
    trial_plan.push_back({static_cast<std::size_t>(plan[2 * k]), static_cast<std::size_t>(plan[2 * k + 1])});
  }
  // What the constructor would throw for (exceptions are not caught in this build).
  flow().reset();
  if (counts.empty()) return 0;
  for (const auto& trial : trial_plan) {
    if (trial.set >= counts.size() || trial.image >= counts[trial.set]) return 0;
  }
  vimg::study::StudyFlowOptions options;
  options.training_s = training_s;
  options.welcome = welcome != 0;
  flow() = std::make_unique<vimg::study::StudyFlow>(counts, trial_plan, static_cast<std::size_t>(completed < 0 ? 0 : completed),
                                                    options, now_s);
  return 1;
}

// 0 welcome, 1 training, 2 rubbing, 3 answering, 4 pause, 5 end (-1 without a flow).
int vimg_study_screen() { return flow() ? static_cast<int>(flow()->screen()) : -1; }
int vimg_study_trial() { return static_cast<int>(flow()->trial()); }
int vimg_study_total() { return static_cast<int>(flow()->total_trials()); }
int vimg_study_set() { return static_cast<int>(flow()->set()); }
int vimg_study_presented() { return static_cast<int>(flow()->presented()); }
int vimg_study_training_picture() { return static_cast<int>(flow()->training_picture()); }
double vimg_study_training_left_s(double now_s) { return flow()->training_left_s(now_s); }
int vimg_study_can_answer() { return flow()->can_answer() ? 1 : 0; }

void vimg_study_begin(double now_s) { flow()->begin(now_s); }
void vimg_study_tick(double now_s) { flow()->tick(now_s); }
void vimg_study_skip_training(double now_s) { flow()->skip_training(now_s); }
void vimg_study_show_training_picture(int image) {
  if (image >= 0) flow()->show_training_picture(static_cast<std::size_t>(image));
}
void vimg_study_resume(double now_s) { flow()->resume(now_s); }

// phase: 0 down, 1 move, 2 up (player/touch_event.hpp).
void vimg_study_touch(double time_s, int finger, int phase, double x_mm, double y_mm) {
  vimg::TouchEvent e;
  e.time_s = time_s;
  e.finger = finger;
  e.phase = phase == 0 ? vimg::TouchPhase::down : (phase == 1 ? vimg::TouchPhase::move : vimg::TouchPhase::up);
  e.x_mm = x_mm;
  e.y_mm = y_mm;
  flow()->touch(e);
}
int vimg_study_answer(double now_s) { return flow()->answer(now_s) ? 1 : 0; }

// 1 and the result kept for vimg_study_result_*, or 0 when the choice is not taken.
int vimg_study_choose(int image, double now_s) {
  if (image < 0) return 0;
  const auto result = flow()->choose(static_cast<std::size_t>(image), now_s);
  if (!result) return 0;
  last_result() = *result;
  return 1;
}
int vimg_study_result_trial() { return static_cast<int>(last_result().trial); }
int vimg_study_result_set() { return static_cast<int>(last_result().set); }
int vimg_study_result_presented() { return static_cast<int>(last_result().presented); }
int vimg_study_result_chosen() { return static_cast<int>(last_result().chosen); }
double vimg_study_result_rub_s() { return last_result().rub_s; }
double vimg_study_result_response_s() { return last_result().response_s; }
double vimg_study_result_path_mm() { return last_result().path_mm; }

}  // extern "C"
