#include "study/separate_output.hpp"

#include <algorithm>
#include <cmath>

#include "storage/export/json_writer.hpp"
#include "study/compare_output_parts.hpp"
#include "study/report_svg.hpp"

namespace vimg::study {

namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:2em;max-width:64em;color:#111}"
    "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #999;padding:0.25em 0.6em;text-align:right}"
    "th{background:#eee}td.name,th.name{text-align:left}.warn{color:#8a3b00}.ok{color:#1d6b2a}"
    ".note{color:#555;font-size:0.9em}figure{display:inline-block;margin:0 2em 1em 0;vertical-align:top}";

double lowest_diagonal(const PerceptionMatrix& m) {
  double low = 1.0;
  for (std::size_t i = 0; i < m.size(); ++i) low = std::min(low, m[i][i]);
  return low;
}

void side(JsonWriter& w, const PerceptionMatrix& m, double bits) {
  w.begin_object();
  w.key("predicted_confusion");
  matrix(w, m);
  w.key("information_transfer_bits");
  w.number(bits);
  w.key("lowest_identified");
  w.number(lowest_diagonal(m));
  w.end_object();
}

std::vector<std::string> labels(const SeparateResult& r) {
  std::vector<std::string> out;
  for (const SeparateImage& im : r.images) out.push_back(im.label);
  return out;
}

std::string percent(double p) { return number_text(100.0 * p, 0) + " %"; }

std::string outcome_sentence(const SeparateResult& r) {
  if (r.already_distinct)
    return "<p class=\"ok\">Every image is already predicted identified at least " + percent(r.target) +
           " of the time: nothing to change, no file written.</p>\n";
  if (r.reached)
    return "<p class=\"ok\">The proposal brings every image to at least " + percent(r.target) + " identified, for a felt change of " +
           number_text(r.total_change_jnd(), 1) + " JNDs over the set.</p>\n";
  return "<p class=\"warn\">The target of " + percent(r.target) +
         " identified is out of reach; the best set found is written, with what limits it below.</p>\n";
}

std::string changes_table(const SeparateResult& r, const std::vector<std::string>& outputs) {
  std::string s = "<table>\n<tr><th class=\"name\">image</th><th class=\"name\">changes</th><th>felt change (JNDs)</th>"
                  "<th>identified before</th><th>after</th><th class=\"name\">written to</th></tr>\n";
  for (std::size_t i = 0; i < r.images.size(); ++i) {
    const SeparateImage& im = r.images[i];
    std::string changes;
    for (const ParameterChange& c : im.changes) changes += (changes.empty() ? "" : "<br>") + xml_text(c.text);
    if (changes.empty()) changes = im.kept ? "kept as it is (--keep)" : "none";
    s += "<tr><td class=\"name\">" + xml_text(im.label) + "</td><td class=\"name\">" + changes + "</td><td>" +
         number_text(im.change_jnd, 1) + "</td><td>" + percent(im.identified_before) + "</td><td>" +
         percent(im.identified_after) + "</td><td class=\"name\">" +
         xml_text(i < outputs.size() && !outputs[i].empty() ? outputs[i] : "\u2013") + "</td></tr>\n";
  }
  return s + "</table>\n";
}

}  // namespace

std::string_view separate_outcome_name(const SeparateResult& r) {
  if (r.already_distinct) return "already_distinct";
  return r.reached ? "reached" : "out_of_reach";
}

std::string separate_json(const SeparateResult& r, const std::vector<std::string>& outputs, const std::string& model_file) {
  JsonWriter w;
  w.begin_object();
  w.key("target");
  w.number(r.target);
  w.key("outcome");
  w.string(separate_outcome_name(r));
  w.key("vary");
  w.begin_array();
  for (std::size_t p = 0; p < kTactileParameterCount; ++p)
    if (r.vary[p]) w.string(tactile_parameter_name(static_cast<TactileParameter>(p)));
  w.end_array();
  w.key("limits");
  w.begin_array();
  for (const std::string& l : r.limits) w.string(l);
  w.end_array();
  w.key("images");
  w.begin_array();
  for (std::size_t i = 0; i < r.images.size(); ++i) {
    const SeparateImage& im = r.images[i];
    w.begin_object();
    w.key("path");
    w.string(im.path);
    w.key("label");
    w.string(im.label);
    w.key("output");
    if (i < outputs.size() && !outputs[i].empty()) {
      w.string(outputs[i]);
    } else {
      w.null();
    }
    w.key("kept");
    w.boolean(im.kept);
    w.key("changes");
    w.begin_array();
    for (const ParameterChange& c : im.changes) {
      w.begin_object();
      w.key("element");
      w.string(c.element);
      w.key("id");
      w.string(c.element_id);
      w.key("parameter");
      w.string(tactile_parameter_name(c.parameter));
      w.key("from");
      w.string(c.from);
      w.key("to");
      w.string(c.to);
      w.key("text");
      w.string(c.text);
      w.end_object();
    }
    w.end_array();
    w.key("change_jnd");
    w.number(im.change_jnd);
    w.key("identified_before");
    w.number(im.identified_before);
    w.key("identified_after");
    w.number(im.identified_after);
    w.end_object();
  }
  w.end_array();
  w.key("before");
  side(w, r.before.predicted_confusion, r.information_before_bits);
  w.key("after");
  side(w, r.confusion_after, r.information_after_bits);
  w.key("total_change_jnd");
  w.number(r.total_change_jnd());
  w.key("variants_rendered");
  w.integer(r.variants_rendered);
  w.key("states_scored");
  w.integer(r.states_scored);
  w.key("actuator");
  describe_actuator(w, r.before.actuator);
  w.key("exploration");
  describe_exploration(w, r.before);
  w.key("model");
  describe_model(w, r.before, model_file);
  w.end_object();
  std::string text = w.take();
  return text + "\n";
}

std::string separate_html(const SeparateResult& r, const std::vector<std::string>& outputs) {
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Proposed changes</title>\n<style>";
  s += kStyle;
  s += "</style>\n</head>\n<body>\n<h1>What to change so that people tell them apart</h1>\n";
  s += outcome_sentence(r);
  s += "<h2>Changes</h2>\n<p class=\"note\">Tactile parameters only; each image moves as a whole. The felt change is the "
       "distance of the proposal from the original in just-noticeable differences of the perception model.</p>\n";
  s += changes_table(r, outputs);
  if (!r.limits.empty()) {
    s += "<h2>What limits it</h2>\n<ul>\n";
    for (const std::string& l : r.limits) s += "<li class=\"warn\">" + xml_text(l) + "</li>\n";
    s += "</ul>\n";
  }
  s += "<h2>Predicted confusion</h2>\n<p class=\"note\">Rows: the image presented; columns: the picture chosen; each row sums "
       "to 1. Information transfer " + number_text(r.information_before_bits, 2) + " bits before, " +
       number_text(r.information_after_bits, 2) + " bits after (at most " +
       number_text(std::log2(static_cast<double>(std::max<std::size_t>(1, r.images.size()))), 2) + ").</p>\n";
  s += "<figure>\n" + heat_map_svg(matrix_heat_map(labels(r), r.before.predicted_confusion, "Before")) + "</figure>\n";
  s += "<figure>\n" + heat_map_svg(matrix_heat_map(labels(r), r.confusion_after, "After")) + "</figure>\n";
  s += setup_html(r.before);
  s += "<p class=\"note\">Written by vimg separate; the search is described in docs/separate.md.</p>\n</body>\n</html>\n";
  return s;
}

}  // namespace vimg::study
