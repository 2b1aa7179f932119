#include "study/compare_output.hpp"
#include "study/compare_output_parts.hpp"

#include <cmath>
#include <cstdio>

#include "storage/atomic_file.hpp"
#include "storage/export/json_writer.hpp"
#include "storage/study/perception_model_file.hpp"
#include "storage/file_extension.hpp"
#include "storage/number_text.hpp"
#include "storage/signal_file.hpp"

namespace vimg::study {

namespace {

std::string_view kind_name(CompareInputKind kind) {
  switch (kind) {
    case CompareInputKind::image: return "image";
    case CompareInputKind::wav_signal: return "wav";
    case CompareInputKind::csv_signal: return "csv";
  }
  return "image";
}

// As profiles name the models (docs/actuators.md).
std::string_view model_name(ResponseModel model) {
  switch (model) {
    case ResponseModel::ideal: return "ideal";
    case ResponseModel::lra: return "lra";
    case ResponseModel::erm: return "erm";
    case ResponseModel::voice_coil: return "voice_coil";
  }
  return "ideal";
}




// One cue's distances of every ordered pair, JNDs.
PerceptionMatrix cue_of(const CueMatrix& cues, std::size_t cue) {
  PerceptionMatrix m(cues.size());
  for (std::size_t i = 0; i < cues.size(); ++i) {
    for (const CueDistances& d : cues[i]) m[i].push_back(d[cue]);
  }
  return m;
}


// A CSV field: quoted (RFC 4180) when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

void matrix(JsonWriter& w, const PerceptionMatrix& m) {
  w.begin_array();
  for (const auto& row : m) {
    w.begin_array();
    for (const double v : row) {
      if (std::isfinite(v)) {
        w.number(v);
      } else {
        w.null();
      }
    }
    w.end_array();
  }
  w.end_array();
}

void describe_actuator(JsonWriter& w, const CompareActuator& a) {
  w.begin_object();
  w.key("name");
  w.string(a.name);
  w.key("file");
  if (a.file.empty()) {
    w.null();
  } else {
    w.string(a.file);
  }
  w.key("model");
  w.string(model_name(a.response.model));
  w.key("resonance_hz");
  w.number(a.response.resonance_hz);
  if (a.response.model == ResponseModel::lra) {
    w.key("q");
    w.number(a.response.q);
  } else if (a.response.model == ResponseModel::voice_coil) {
    w.key("low_hz");
    w.number(a.response.low_hz);
    w.key("high_hz");
    w.number(a.response.high_hz);
  } else if (a.response.model == ResponseModel::erm) {
    w.key("spin_up_s");
    w.number(a.response.spin_up_s);
    w.key("spin_down_s");
    w.number(a.response.spin_down_s);
  }
  w.key("signal");
  w.string("acceleration");
  w.end_object();
}

void describe_exploration(JsonWriter& w, const CompareResult& r) {
  w.begin_object();
  if (r.exploration) {
    const Exploration& e = *r.exploration;
    w.key("kind");
    w.string("standard");
    w.key("description");
    w.string(describe(e));
    w.key("speeds_mm_per_s");
    w.begin_array();
    for (const double v : e.spec.speeds_mm_per_s) w.number(v);
    w.end_array();
    w.key("pass_spacing_mm");
    w.number(e.pass_spacing_mm);
    w.key("event_rate_hz");
    w.number(e.spec.event_rate_hz);
    w.key("gap_s");
    w.number(e.spec.gap_s);
    w.key("duration_s");
    w.number(e.duration_s);
  } else {
    w.key("kind");
    w.string(r.gesture_files.empty() ? "none (every input is a rendered signal)" : "gestures");
    w.key("gesture_files");
    w.begin_array();
    for (const std::string& f : r.gesture_files) w.string(f);
    w.end_array();
  }
  w.end_object();
}

void describe_model(JsonWriter& w, const CompareResult& r, const std::string& model_file) {
  w.begin_object();
  w.key("model_file");
  if (model_file.empty()) {
    w.null();
  } else {
    w.string(model_file);
  }
  w.key("documentation");
  w.string("docs/perception.md, docs/studies.md");
  w.key("full_scale_peak_acceleration_mps2");
  w.number(r.calibration.full_scale_peak_acceleration_mps2);
  w.key("threshold_at_250hz_peak_displacement_m");
  w.number(r.calibration.threshold_at_250hz_peak_displacement_m);
  w.key("level_jnd_db");
  w.number(kLevelJndDb);
  w.key("frequency_weber_fraction");
  w.number(kFrequencyWeberFraction);
  w.key("choice_model");
  w.string("p(j|i) = (1 - lapse) eta_ij / sum_k eta_ik + lapse / n, eta = Phi(-d'/2) / Phi(d'/2), d'_ij = sqrt(sum_c "
           "(k w_c d_c,ij / sqrt(1 + (G R_c)^2))^2), k = 0.954, R_c = k w_c (range of the set on cue c)");
  w.key("context_noise_per_d_prime");
  w.number(kContextNoisePerDPrime);
  write_discrimination_constants(w, r.discrimination);
  w.key("likely_confused_p");
  w.number(r.choice.likely_confused_p);
  w.end_object();
}


std::string compare_json(const CompareResult& r, const std::string& model_file) {
  JsonWriter w;
  w.begin_object();
  w.key("images");
  w.begin_array();
  for (const CompareInput& in : r.inputs) w.string(in.path);
  w.end_array();
  w.key("labels");
  w.begin_array();
  for (const CompareInput& in : r.inputs) w.string(in.label);
  w.end_array();
  w.key("kinds");
  w.begin_array();
  for (const CompareInput& in : r.inputs) w.string(kind_name(in.kind));
  w.end_array();
  w.key("stsim");
  matrix(w, r.stsim);
  w.key("cue_distances_jnd");
  w.begin_object();
  for (std::size_t c = 0; c < kCueCount; ++c) {
    w.key(std::string(cue_name(c)));
    matrix(w, cue_of(r.cues, c));
  }
  w.end_object();
  w.key("distance_jnd");
  matrix(w, r.distance_jnd);
  w.key("predicted_confusion");
  matrix(w, r.predicted_confusion);
  w.key("likely_confused");
  w.begin_array();
  for (const ConfusedPair& pair : r.likely_confused) {
    w.begin_object();
    w.key("a");
    w.integer(static_cast<long long>(pair.a));
    w.key("b");
    w.integer(static_cast<long long>(pair.b));
    w.key("p");
    w.number(pair.p);
    w.end_object();
  }
  w.end_array();
  w.key("warnings");
  w.begin_array();
  for (const std::string& text : r.warnings) w.string(text);
  w.end_array();
  w.key("sample_rate_hz");
  w.number(kCompareRateHz);
  w.key("durations_s");
  w.begin_array();
  for (const CompareInput& in : r.inputs) w.number(in.duration_s);
  w.end_array();
  w.key("canvas_mm");
  if (r.canvas_width_mm) {
    w.begin_object();
    w.key("width");
    w.number(*r.canvas_width_mm);
    w.key("height");
    w.number(*r.canvas_height_mm);
    w.end_object();
  } else {
    w.null();
  }
  w.key("actuator");
  describe_actuator(w, r.actuator);
  w.key("exploration");
  describe_exploration(w, r);
  w.key("model");
  describe_model(w, r, model_file);
  w.end_object();
  std::string text = w.take();
  text += '\n';
  return text;
}

std::string compare_csv(const CompareResult& r) {
  std::string out = "image_i,image_j,stsim";
  for (std::size_t c = 0; c < kCueCount; ++c) out += "," + std::string(cue_name(c)) + "_jnd";
  out += ",distance_jnd,predicted_p\n";
  const std::size_t n = r.inputs.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      out += csv_field(r.inputs[i].path) + ',' + csv_field(r.inputs[j].path) + ',';
      if (std::isfinite(r.stsim[i][j])) append_decimal(out, r.stsim[i][j]);
      for (std::size_t c = 0; c < kCueCount; ++c) {
        out += ',';
        append_decimal(out, r.cues[i][j][c]);
      }
      out += ',';
      append_decimal(out, r.distance_jnd[i][j]);
      out += ',';
      append_decimal(out, r.predicted_confusion[i][j]);
      out += '\n';
    }
  }
  return out;
}

bool is_compare_output(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".json" || ext == ".html" || ext == ".htm" || ext == ".csv";
}

std::string compare_output_text(const std::filesystem::path& path, const CompareResult& result,
                                const std::string& model_file) {
  const std::string ext = lower_extension(path);
  return ext == ".json" ? compare_json(result, model_file) : ext == ".csv" ? compare_csv(result) : compare_html(result);
}

std::optional<std::string> write_compare_output(const std::filesystem::path& path, const CompareResult& result) {
  return write_file_atomically(path, compare_output_text(path, result));
}

}  // namespace vimg::study
