// The HTML page of `vimg compare --out X.html` (compare_output.hpp): self-contained, readable
// offline. The heat maps are the study report's (study/report_svg.hpp), so that a prediction and
// the measured confusion of `vimg study report` look alike.
#include <cmath>
#include <cstdio>

#include "study/compare_output.hpp"
#include "study/compare_output_parts.hpp"
#include "study/report_svg.hpp"

namespace vimg::study {

namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:2em;max-width:60em;color:#111}"
    "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #999;padding:0.25em 0.6em;text-align:right}"
    "th{background:#eee}td.name,th.name{text-align:left}.warn{color:#8a3b00}.note{color:#555;font-size:0.9em}"
    "figure{display:inline-block;margin:0 2em 1em 0;vertical-align:top}";


std::vector<std::string> labels(const CompareResult& r) {
  std::vector<std::string> out;
  for (const CompareInput& in : r.inputs) out.push_back(in.label);
  return out;
}


std::string distance_table(const CompareResult& r) {
  std::string cues;
  for (std::size_t c = 0; c < kCueCount; ++c) cues += (c ? ", " : "") + std::string(cue_name(c));
  std::string s =
      "<p class=\"note\">How far apart each pair is, in just-noticeable differences (1 JND: told apart in 75 % of "
      "two-alternative trials): the combined distance, then per cue (" + xml_text(cues) + ").</p>\n";
  s += "<table>\n<tr><th class=\"name\">JNDs</th>";
  for (const CompareInput& in : r.inputs) s += "<th>" + xml_text(in.label) + "</th>";
  s += "</tr>\n";
  for (std::size_t i = 0; i < r.inputs.size(); ++i) {
    s += "<tr><th class=\"name\">" + xml_text(r.inputs[i].label) + "</th>";
    for (std::size_t j = 0; j < r.inputs.size(); ++j) {
      std::string per_cue;
      for (std::size_t c = 0; c < kCueCount; ++c) per_cue += (c ? ", " : "") + number_text(r.cues[i][j][c], 1);
      s += "<td>" + number_text(r.distance_jnd[i][j], 1) + " <span class=\"note\">(" + per_cue + ")</span></td>";
    }
    s += "</tr>\n";
  }
  return s + "</table>\n";
}

std::string stsim_table(const CompareResult& r) {
  std::string s =
      "<p class=\"note\">ST-SIM, the codec-distortion metric (vibromaf's values): how alike the waveforms are, block "
      "by block, phase included; 1 the same waveform. Of the image \u2193 against the reference \u2192 over their common "
      "length; \u2013 where it has no value. Values far above 1 (up to millions) are the metric's own where a "
      "reference holds almost no energy, as an actuator's ring does (docs/stsim.md). It does not decide the "
      "prediction: two vibrations felt alike may have unrelated waveforms.</p>\n";
  s += "<table>\n<tr><th class=\"name\">ST-SIM of \u2193 against reference \u2192</th>";
  for (const CompareInput& in : r.inputs) s += "<th>" + xml_text(in.label) + "</th>";
  s += "</tr>\n";
  for (std::size_t i = 0; i < r.inputs.size(); ++i) {
    s += "<tr><th class=\"name\">" + xml_text(r.inputs[i].label) + "</th>";
    for (std::size_t j = 0; j < r.inputs.size(); ++j) s += "<td>" + number_text(r.stsim[i][j], 3) + "</td>";
    s += "</tr>\n";
  }
  return s + "</table>\n";
}


}  // namespace

std::string number_text(double v, int decimals) {
  if (!std::isfinite(v)) return "\u2013";
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

HeatMap matrix_heat_map(std::vector<std::string> labels, const PerceptionMatrix& m, std::string title) {
  HeatMap map;
  map.title = std::move(title);
  map.labels = std::move(labels);
  for (const auto& row : m) {
    std::vector<std::optional<double>> shade;
    std::vector<std::string> cells;
    for (const double v : row) {
      shade.push_back(std::isfinite(v) ? std::optional(v) : std::nullopt);
      cells.push_back(number_text(v, 2));
    }
    map.shade.push_back(std::move(shade));
    map.cells.push_back(std::move(cells));
  }
  return map;
}

std::string setup_html(const CompareResult& r) {
  std::string s = "<h2>How the images were felt</h2>\n<ul>\n";
  const CompareActuator& a = r.actuator;
  s += "<li>Actuator: " + xml_text(a.name) + (a.file.empty() ? " (built in)" : " (" + xml_text(a.file) + ")") +
       "; each image's predicted acceleration at 8 kHz.</li>\n";
  if (r.canvas_width_mm) {
    s += "<li>Canvas: " + number_text(*r.canvas_width_mm, 1) + " \u00d7 " + number_text(*r.canvas_height_mm, 1) + " mm.</li>\n";
  }
  if (r.exploration) {
    s += "<li>Exploration: the standard one, " + xml_text(describe(*r.exploration)) + ".</li>\n";
  } else if (!r.gesture_files.empty()) {
    std::string files;
    for (const std::string& f : r.gesture_files) files += (files.empty() ? "" : ", ") + f;
    s += "<li>Exploration: the gestures " + xml_text(files) + ", one after another.</li>\n";
  }
  for (const CompareInput& in : r.inputs) {
    if (in.kind != CompareInputKind::image) {
      s += "<li>" + xml_text(in.label) + " is a rendered signal, compared as it is (" + number_text(in.duration_s, 1) + " s).</li>\n";
    }
  }
  std::string weights;
  for (std::size_t c = 0; c < kCueCount; ++c) {
    weights += (c ? ", " : "") + std::string(cue_name(c)) + " " + number_text(r.discrimination.cue_weight[c], 2);
  }
  s += "<li>Model: the cues of docs/perception.md (full scale " +
       number_text(r.calibration.full_scale_peak_acceleration_mps2, 2) + " m/s\u00b2 peak; JNDs " +
       number_text(kLevelJndDb, 1) + " dB of level, " + number_text(100.0 * kFrequencyWeberFraction, 0) +
       " % of frequency) and its identification model (context noise " + number_text(kContextNoisePerDPrime, 2) +
       " per d' of the set's range on each cue), lapse rate " + number_text(r.discrimination.lapse_rate, 3) + ", cue weights " + xml_text(weights) +
       "; a pair is likely confused from p = " + number_text(r.choice.likely_confused_p, 2) + ".</li>\n</ul>\n";
  return s;
}

std::string compare_html(const CompareResult& r) {
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Predicted confusion</title>\n<style>";
  s += kStyle;
  s += "</style>\n</head>\n<body>\n<h1>Will people tell them apart?</h1>\n";
  s += "<p class=\"note\">The predicted confusion of a matching test on these images: rows are the image presented, columns the "
       "picture chosen, each row sums to 1.</p>\n";
  s += "<h2>Warnings</h2>\n";
  if (r.warnings.empty()) {
    s += "<p>No pair is likely to be confused (p below " + number_text(r.choice.likely_confused_p, 2) + ").</p>\n";
  } else {
    s += "<ul>\n";
    for (const std::string& w : r.warnings) s += "<li class=\"warn\">" + xml_text(w) + "</li>\n";
    s += "</ul>\n";
  }
  s += "<figure>\n" + heat_map_svg(matrix_heat_map(labels(r), r.predicted_confusion, "Predicted confusion")) + "</figure>\n";
  s += "<h2>Distances</h2>\n" + distance_table(r);
  s += "<h2>ST-SIM</h2>\n" + stsim_table(r);
  s += setup_html(r);
  s += "<p class=\"note\">Written by vimg compare; the model is described in docs/perception.md and docs/studies.md.</p>\n";
  s += "</body>\n</html>\n";
  return s;
}

}  // namespace vimg::study
