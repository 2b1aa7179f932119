// The C++ forward pass of the learned touch predictor against the training script's own (numpy):
// tests/touch_prediction/learned_probes.hpp holds probe histories and what
// scripts/train_touch_predictor.py predicts for them with the committed weights (the ctest
// touch_predictor_learned_probes checks that file against the weights; this test checks the C++).
#include <gtest/gtest.h>

#include "primitives/touch_prediction/finger_predictor.hpp"
#include "tests/touch_prediction/learned_probes.hpp"

namespace vimg {
namespace {

TEST(LearnedProbes, TheCppForwardPassGivesTheScriptsPredictions) {
  int compared = 0;
  for (int k = 0; k < learned_probes::kHistories; ++k) {
    FingerHistory h;
    for (const learned_probes::ProbeEvent& e : learned_probes::kEvents) {
      if (e.history == k) add_finger_event(h, e.time_s, e.x_mm, e.y_mm);
    }
    for (const learned_probes::ProbePrediction& p : learned_probes::kPredictions) {
      if (p.history != k) continue;
      const PredictedPosition q = predict_finger(h, p.horizon_s, TouchPredictionModel::learned);
      EXPECT_NEAR(q.x_mm, p.x_mm, 1e-9) << "history " << k << " horizon " << p.horizon_s;
      EXPECT_NEAR(q.y_mm, p.y_mm, 1e-9) << "history " << k << " horizon " << p.horizon_s;
      ++compared;
    }
  }
  EXPECT_GE(compared, 30);
}

}  // namespace
}  // namespace vimg
