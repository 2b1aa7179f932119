// The C functions the page calls (web/site/vimg.js and worklet.js); one WebRenderer per instance.
// Buffers passed in are owned by the caller (allocated with malloc from JavaScript); buffers
// returned stay valid until the next call that fills them.
#include <cstddef>
#include <string>
#include <string_view>

#include "player/render_defaults.hpp"
#include "primitives/touch_prediction/circling_finger.hpp"
#include "primitives/touch_prediction/touch_latency_defaults.hpp"
#include "web/wasm/picture_json.hpp"
#include "web/wasm/web_renderer.hpp"

namespace {
vimg::WebRenderer& renderer() {
  static vimg::WebRenderer r;
  return r;
}
std::string& picture() {
  static std::string json;
  return json;
}
// phase: 0 down, 1 move, 2 up (player/touch_event.hpp).
vimg::TouchEvent touch_event(double time_s, int finger, int phase, double x_mm, double y_mm, double pressure) {
  vimg::TouchEvent e;
  e.time_s = time_s;
  e.finger = finger;
  e.phase = phase == 0 ? vimg::TouchPhase::down : phase == 1 ? vimg::TouchPhase::move : vimg::TouchPhase::up;
  e.x_mm = x_mm;
  e.y_mm = y_mm;
  e.pressure = pressure;
  return e;
}
}  // namespace

extern "C" {

int vimg_load_vsc(const char* bytes, int size) {
  return renderer().load_vsc(std::string_view(bytes, static_cast<std::size_t>(size))) ? 1 : 0;
}
const char* vimg_last_error() { return renderer().error().c_str(); }
double vimg_canvas_width_mm() { return renderer().image().image.width_mm; }
double vimg_canvas_height_mm() { return renderer().image().image.height_mm; }

// The picture of the loaded image (web/wasm/picture_json.hpp), NUL-terminated.
const char* vimg_picture_json() {
  picture() = vimg::picture_json(renderer().image().image);
  return picture().c_str();
}

int vimg_render_gesture(const char* csv, int size, double rate_hz) {
  if (!renderer().render_gesture(std::string_view(csv, static_cast<std::size_t>(size)), rate_hz)) return -1;
  return static_cast<int>(renderer().rendered().size());
}
const float* vimg_rendered_samples() { return renderer().rendered().data(); }
double vimg_rendered_start_s() { return renderer().rendered_start_s(); }

void vimg_live_start(double rate_hz) { renderer().live_start(rate_hz); }
// phase: 0 down, 1 move, 2 up (player/touch_event.hpp); time on the live stream's clock.
void vimg_live_event(double time_s, int finger, int phase, double x_mm, double y_mm, double pressure) {
  renderer().live_event(touch_event(time_s, finger, phase, x_mm, y_mm, pressure));
}
const float* vimg_live_render(int frames) { return renderer().live_render(static_cast<std::size_t>(frames)).data(); }
double vimg_live_time_s() { return renderer().live_time_s(); }
int vimg_live_contacts() { return static_cast<int>(renderer().live_contacts()); }

// Touch-latency compensation (docs/latency.md): the live stream predicts each finger horizon_s
// ahead (0: off); the page's defaults and bound are the C++ ones (touch_latency_defaults.hpp).
void vimg_live_set_prediction(double horizon_s) { renderer().live_set_prediction(horizon_s); }
double vimg_live_prediction_horizon_s() { return renderer().live_prediction_horizon_s(); }
double vimg_touch_latency_default_ms(int mouse_or_pen) {
  return (mouse_or_pen != 0 ? vimg::kDefaultMousePanelLatency_s : vimg::kDefaultTouchPanelLatency_s) * 1e3;
}
double vimg_touch_latency_max_ms() { return vimg::kMaxTouchPanelLatency_s * 1e3; }

// The same event queued at its time on the live stream's clock (WebRenderer::live_event_at).
void vimg_live_event_at(double time_s, int finger, int phase, double x_mm, double y_mm, double pressure) {
  renderer().live_event_at(touch_event(time_s, finger, phase, x_mm, y_mm, pressure));
}

// The defaults the page shows and uses (player/render_defaults.hpp): none are written in JavaScript.
double vimg_default_render_rate_hz() { return vimg::kDefaultRenderRateHz; }
int vimg_max_live_fingers() { return vimg::kMaxLiveFingers; }

// The predictor's models by index (TouchPredictionModel), for the benchmark below.
int vimg_prediction_model_count() { return vimg::kTouchPredictionModelCount; }
const char* vimg_prediction_model_name(int model) {
  if (model < 0 || model >= vimg_prediction_model_count()) return "";
  return vimg::touch_prediction_model_name(static_cast<vimg::TouchPredictionModel>(model)).data();
}
// The cost of one prediction (bench/web_render_bench.mjs): `repeats` predictions of the workload
// touch_prediction_bench's BM_Predict measures natively (circling_finger.hpp). Returns a sum of the
// positions so that nothing is optimized away.
double vimg_bench_predict(int repeats, int model) {
  const vimg::FingerHistory h = vimg::circling_finger_history();
  const auto m = static_cast<vimg::TouchPredictionModel>(model);
  double horizon_s = 0.033;
  double sum = 0.0;
  for (int i = 0; i < repeats; ++i) {
    const vimg::PredictedPosition p = vimg::predict_finger(h, horizon_s, m);
    sum += p.x_mm + p.y_mm;
    horizon_s = vimg::next_bench_horizon_s(horizon_s);
  }
  return sum;
}

}  // extern "C"
