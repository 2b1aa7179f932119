// The matching test's procedure (study/study_flow.hpp) with a fake clock: screens in
// order, training per set, what a trial measures, resuming inside and at the edge of a set.
#include "study/study_flow.hpp"

#include <gtest/gtest.h>

namespace vimg::study {
namespace {

using Plan = std::vector<MatchingTrialPlan>;

// Two sets of two images, two trials each: trials 1-2 in set 0, 3-4 in set 1.
const Plan kPlan{{0, 1}, {0, 0}, {1, 0}, {1, 1}};

TouchEvent touch(double t, TouchPhase phase, double x, double y, int finger = 0) {
  TouchEvent e;
  e.time_s = t;
  e.phase = phase;
  e.x_mm = x;
  e.y_mm = y;
  e.finger = finger;
  return e;
}

// Rubs from (0,0) to (3,4) between t and t + 1 and answers at t + 2.
void rub_and_answer(StudyFlow& flow, double t) {
  flow.touch(touch(t, TouchPhase::down, 0, 0));
  flow.touch(touch(t + 0.5, TouchPhase::move, 3, 0));
  flow.touch(touch(t + 1.0, TouchPhase::up, 3, 4));
  ASSERT_TRUE(flow.answer(t + 2.0));
}

TEST(StudyFlow, WelcomeTrainingTrialsPauseTrainingTrialsEnd) {
  StudyFlow flow({2, 2}, kPlan, 0, StudyFlowOptions{60.0, true}, 0.0);
  EXPECT_EQ(flow.screen(), StudyScreen::welcome);
  EXPECT_EQ(flow.trial(), 1u);
  EXPECT_EQ(flow.total_trials(), 4u);
  flow.begin(10.0);
  EXPECT_EQ(flow.screen(), StudyScreen::training);
  EXPECT_DOUBLE_EQ(flow.training_left_s(40.0), 30.0);
  flow.tick(69.9);
  EXPECT_EQ(flow.screen(), StudyScreen::training);
  flow.tick(70.0);  // the countdown ends the training
  EXPECT_EQ(flow.screen(), StudyScreen::rubbing);
  EXPECT_EQ(flow.presented(), 1u);

  rub_and_answer(flow, 100.0);
  EXPECT_EQ(flow.screen(), StudyScreen::answering);
  auto first = flow.choose(1, 103.5);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->trial, 1u);
  EXPECT_EQ(first->set, 0u);
  EXPECT_EQ(first->presented, 1u);
  EXPECT_EQ(first->chosen, 1u);
  EXPECT_DOUBLE_EQ(first->rub_s, 2.0);       // first touch to Answer
  EXPECT_DOUBLE_EQ(first->response_s, 1.5);  // Answer to the tap
  EXPECT_DOUBLE_EQ(first->path_mm, 7.0);     // 3 + 4
  EXPECT_EQ(flow.screen(), StudyScreen::rubbing);  // the next trial of the same set at once

  rub_and_answer(flow, 200.0);
  auto second = flow.choose(1, 202.0);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->presented, 0u);
  EXPECT_EQ(flow.screen(), StudyScreen::pause);  // set 0 done
  EXPECT_EQ(flow.set(), 1u);
  flow.resume(300.0);
  EXPECT_EQ(flow.screen(), StudyScreen::training);  // the next set is trained on too
  flow.skip_training(301.0);                        // the experimenter's key
  EXPECT_EQ(flow.screen(), StudyScreen::rubbing);
  EXPECT_EQ(flow.trial(), 3u);

  rub_and_answer(flow, 400.0);
  ASSERT_TRUE(flow.choose(0, 402.0).has_value());
  rub_and_answer(flow, 500.0);
  auto last = flow.choose(0, 502.0);
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->trial, 4u);
  EXPECT_EQ(flow.screen(), StudyScreen::end);
  EXPECT_EQ(flow.trial(), 5u);
}

TEST(StudyFlow, AnswerNeedsATouchAndAChoiceNeedsTheAnswerScreen) {
  StudyFlow flow({2, 2}, kPlan, 0, StudyFlowOptions{0.0, false}, 0.0);
  EXPECT_EQ(flow.screen(), StudyScreen::rubbing);  // no welcome, no training
  EXPECT_FALSE(flow.choose(0, 1.0).has_value());
  EXPECT_FALSE(flow.can_answer());
  EXPECT_FALSE(flow.answer(1.0));
  EXPECT_EQ(flow.screen(), StudyScreen::rubbing);
  flow.touch(touch(2.0, TouchPhase::down, 5, 5));
  EXPECT_TRUE(flow.can_answer());
  EXPECT_TRUE(flow.answer(2.5));
  EXPECT_FALSE(flow.choose(2, 3.0).has_value());  // set 0 has two images
  EXPECT_EQ(flow.screen(), StudyScreen::answering);
  const auto result = flow.choose(0, 3.0);
  ASSERT_TRUE(result.has_value());
  EXPECT_DOUBLE_EQ(result->rub_s, 0.5);
  EXPECT_DOUBLE_EQ(result->path_mm, 0.0);
  // The next trial starts afresh: no touch yet.
  EXPECT_FALSE(flow.can_answer());
}

TEST(StudyFlow, PathsOfSeveralFingersAddAndTouchesOutsideRubbingDoNotCount) {
  StudyFlow flow({2, 2}, kPlan, 0, StudyFlowOptions{30.0, false}, 0.0);
  ASSERT_EQ(flow.screen(), StudyScreen::training);
  flow.touch(touch(1.0, TouchPhase::down, 0, 0));
  flow.touch(touch(2.0, TouchPhase::move, 100, 0));  // training: felt, not measured
  flow.tick(30.0);
  ASSERT_EQ(flow.screen(), StudyScreen::rubbing);
  // Finger 0 was already down: its first move starts its path.
  flow.touch(touch(31.0, TouchPhase::move, 10, 0));
  flow.touch(touch(31.5, TouchPhase::move, 10, 10));
  flow.touch(touch(32.0, TouchPhase::down, 50, 50, 1));
  flow.touch(touch(32.5, TouchPhase::move, 50, 56, 1));
  flow.touch(touch(33.0, TouchPhase::up, 50, 56, 1));
  flow.touch(touch(33.0, TouchPhase::up, 10, 12));
  ASSERT_TRUE(flow.answer(34.0));
  flow.touch(touch(34.5, TouchPhase::down, 0, 0));  // answering: ignored
  flow.touch(touch(34.6, TouchPhase::move, 90, 0));
  const auto result = flow.choose(1, 35.0);
  ASSERT_TRUE(result.has_value());
  EXPECT_DOUBLE_EQ(result->path_mm, 10.0 + 6.0 + 2.0);
  EXPECT_DOUBLE_EQ(result->rub_s, 3.0);  // from the first event of the trial (31.0)
}

TEST(StudyFlow, TrainingShowsTheChosenPictureOfTheSet) {
  StudyFlow flow({3, 2}, Plan{{0, 2}, {1, 1}}, 0, StudyFlowOptions{10.0, false}, 0.0);
  EXPECT_EQ(flow.training_picture(), 0u);
  flow.show_training_picture(2);
  EXPECT_EQ(flow.training_picture(), 2u);
  flow.show_training_picture(3);  // no such picture
  EXPECT_EQ(flow.training_picture(), 2u);
  EXPECT_EQ(flow.images_in_set(), 3u);
}

TEST(StudyFlow, ResumingInsideASetSkipsItsTrainingAndAtItsFirstTrialTrainsOnIt) {
  // Trial 2 (the second of set 0) next: set 0 has begun, no training.
  StudyFlow inside({2, 2}, kPlan, 1, StudyFlowOptions{60.0, true}, 0.0);
  EXPECT_EQ(inside.trial(), 2u);
  inside.begin(1.0);
  EXPECT_EQ(inside.screen(), StudyScreen::rubbing);
  EXPECT_EQ(inside.presented(), 0u);
  // Trial 3 (the first of set 1) next: training on set 1 first.
  StudyFlow edge({2, 2}, kPlan, 2, StudyFlowOptions{60.0, true}, 0.0);
  EXPECT_EQ(edge.set(), 1u);
  edge.begin(1.0);
  EXPECT_EQ(edge.screen(), StudyScreen::training);
  // All done: the end at once.
  StudyFlow done({2, 2}, kPlan, 4, StudyFlowOptions{60.0, true}, 0.0);
  EXPECT_EQ(done.screen(), StudyScreen::end);
}

TEST(StudyFlow, RefusesAPlanNamingImagesTheSetsDoNotHave) {
  EXPECT_THROW(StudyFlow({2}, Plan{{0, 2}}, 0, {}, 0.0), std::invalid_argument);
  EXPECT_THROW(StudyFlow({2}, Plan{{1, 0}}, 0, {}, 0.0), std::invalid_argument);
  EXPECT_THROW(StudyFlow({}, Plan{}, 0, {}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace vimg::player_app
