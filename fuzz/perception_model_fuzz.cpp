// Fuzzes the reader of MODEL.json (storage/study/perception_model_file.hpp, what `vimg compare
// --model` reads): any bytes give one located error or constants within their documented ranges,
// never a crash; a model that reads is written again by the writer and reads back to the same
// constants and the same actuator (as given, by name and by response).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "check_messages.hpp"
#include "storage/study/perception_model_file.hpp"

namespace {

void check_constants(const vimg::DiscriminationConstants& c) {
  if (!(c.temperature_jnd > 0.0 && std::isfinite(c.temperature_jnd))) std::abort();
  if (!(c.lapse_rate >= 0.0 && c.lapse_rate <= 1.0)) std::abort();
  for (const double w : c.cue_weight) {
    if (!(w >= 0.0 && std::isfinite(w))) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::PerceptionModelLoadResult r = vimg::parse_perception_model(text, "fuzz.json");
  if (r.model.has_value() == vimg::has_errors(r.diagnostics)) std::abort();  // a model iff no error
  if (r.diagnostics.size() > 1) std::abort();  // the first problem stops the reader
  vimg::fuzz::check_messages(r.diagnostics);
  for (const vimg::Diagnostic& d : r.diagnostics) {
    if (d.line < 1) std::abort();  // every problem is located
  }
  if (!r.model) return 0;
  check_constants(r.model->constants);
  const vimg::PerceptionModelLoadResult back = vimg::parse_perception_model(vimg::perception_model_json(*r.model), "back.json");
  if (!back.model) std::abort();
  const vimg::DiscriminationConstants& a = r.model->constants;
  const vimg::DiscriminationConstants& b = back.model->constants;
  if (a.temperature_jnd != b.temperature_jnd || a.lapse_rate != b.lapse_rate || a.cue_weight != b.cue_weight) std::abort();
  if (back.model->study != r.model->study) std::abort();
  const vimg::ModelActuator& x = r.model->actuator;
  const vimg::ModelActuator& y = back.model->actuator;
  if (x.given != y.given || x.name != y.name || x.response.has_value() != y.response.has_value()) std::abort();
  if (x.response) {
    const vimg::ResponseParams& u = *x.response;
    const vimg::ResponseParams& v = *y.response;
    if (u.model != v.model || u.resonance_hz != v.resonance_hz || u.q != v.q || u.low_hz != v.low_hz || u.high_hz != v.high_hz ||
        u.spin_up_s != v.spin_up_s || u.spin_down_s != v.spin_down_s)
      std::abort();
    if (!(u.resonance_hz > 0.0 && u.q > 0.0 && u.low_hz > 0.0 && u.high_hz > 0.0 && u.spin_up_s > 0.0 && u.spin_down_s > 0.0))
      std::abort();
  }
  return 0;
}
