// `vimg gesture predict G.csv --ahead-ms H [--model none|linear|fitted|learned] --out P.csv`: each row of a
// gesture with where the touch predictor puts its finger H ms later (player/gesture_prediction.hpp,
// docs/latency.md).
#include <cstdio>
#include <memory>
#include <string>

#include "cli/command.hpp"
#include "storage/gesture_csv.hpp"
#include "player/gesture_prediction.hpp"
#include "storage/atomic_file.hpp"
#include "storage/gesture_prediction_csv.hpp"

namespace vimg::cli {

namespace {

constexpr double kMaxAheadMs = 1000.0;

struct PredictArgs {
  std::string gesture, out, model = std::string(touch_prediction_model_name(kDefaultTouchPredictionModel));
  double ahead_ms = 0.0;
};

int run_predict(const PredictArgs& a) {
  const std::optional<TouchPredictionModel> model = parse_touch_prediction_model(a.model);
  if (!model) return usage_error("vimg gesture predict", "--model must be none, linear, fitted or learned: '" + a.model + "'");
  const GestureParseResult gesture = load_gesture_file(a.gesture);
  for (const std::string& e : gesture.errors) std::fprintf(stderr, "%s\n", e.c_str());
  if (!gesture.ok()) return kExitFailure;
  const std::string text = write_predicted_gesture_csv(predict_gesture(*gesture.gesture, a.ahead_ms * 1e-3, *model));
  // A new output takes the gesture's permission bits, as cp's copy.
  if (const auto error = write_file_atomically(a.out, text, NewFileMode::of(a.gesture))) {
    std::fprintf(stderr, "vimg gesture predict: %s\n", error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void add_gesture_predict(CLI::App& gesture, int& exit_code) {
  CLI::App* sub = gesture.add_subcommand(
      "predict", "each row of a gesture with where the touch predictor puts its finger --ahead-ms later "
                 "(time_s,finger,x_mm,y_mm,predicted_x_mm,predicted_y_mm)");
  auto a = std::make_shared<PredictArgs>();
  sub->add_option("GESTURE", a->gesture, "the gesture CSV (time_s,finger,x_mm,y_mm,pressure,phase)")->required();
  sub->add_option("--ahead-ms", a->ahead_ms, "how far ahead, in ms (decimals allowed, 0 to 1000)")
      ->required()
      ->check(cmdline::finite_in(0.0, kMaxAheadMs));
  sub->add_option("--model", a->model, "none (the last position), linear (the last velocity), fitted (the filter "
                                       "fitted on real traces) or learned (default: the small network trained on "
                                       "real traces, docs/latency.md)")
      ->check(CLI::IsMember({"none", "linear", "fitted", "learned"}));
  sub->add_option("--out", a->out, "output CSV (written atomically)")->required();
  sub->footer("Causal: a row's prediction uses that row and the earlier rows of its stroke only. Down and up rows "
              "give their own position (nothing is predicted past a lift). Gesture limits as vimg render's "
              "(docs/limits.md).");
  sub->callback([a, &exit_code] { exit_code = run_predict(*a); });
}

}  // namespace vimg::cli
