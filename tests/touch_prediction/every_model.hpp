#pragma once
// Every model of TouchPredictionModel, read from the enum itself, so a test written over it covers
// a model the day it is added: the values from 0 up whose name parses back to them.
// touch_prediction_model_name() switches over the enum without a default, so -Wswitch (an error
// here) makes every new value name itself, and `--model NAME` needs the name to parse.
#include <vector>

#include "primitives/touch_prediction/finger_predictor.hpp"

namespace vimg::test {

inline std::vector<TouchPredictionModel> every_touch_prediction_model() {
  std::vector<TouchPredictionModel> models;
  for (int value = 0; value <= 255; ++value) {
    const auto model = static_cast<TouchPredictionModel>(value);
    if (parse_touch_prediction_model(touch_prediction_model_name(model)) != model) break;
    models.push_back(model);
  }
  return models;
}

}  // namespace vimg::test
