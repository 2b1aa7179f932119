#include "study/separate_space.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "storage/number_text.hpp"
#include "storage/parameter_table.hpp"

namespace vimg::study {

namespace {

constexpr std::array<std::string_view, kTactileParameterCount> kNames = {"period", "relief", "pattern",
                                                                         "gain",   "frequency", "damping"};
constexpr std::array<std::string_view, kTactileParameterCount> kUnits = {"mm", "mm", "", "", "Hz", ""};
constexpr std::array<StepRange, kTactileParameterCount> kSteps = {
    StepRange{-6, 6}, StepRange{-4, 4}, StepRange{0, 3}, StepRange{-8, 3}, StepRange{-6, 6}, StepRange{-3, 3}};
constexpr std::array<SurfacePattern, 3> kPatterns = {SurfacePattern::sine, SurfacePattern::square,
                                                     SurfacePattern::triangle};

std::size_t at(TactileParameter p) { return static_cast<std::size_t>(p); }

// Three significant digits: what a designer types.
double round_for_people(double v) {
  if (!(v > 0.0) || !std::isfinite(v)) return v;
  const double scale = std::pow(10.0, 2 - static_cast<int>(std::floor(std::log10(v))));
  return std::round(v * scale) / scale;
}

double scaled(double value, double factor, ParameterOwner owner, std::string_view name) {
  const ParameterSpec* spec = find_parameter(owner, name);
  double v = round_for_people(value * factor);
  // A gain to 0.01, never rounded to silence.
  if (name == "gain") v = value > 0.0 ? std::max(0.01, std::round(value * factor * 100.0) / 100.0) : value;
  return spec ? clamp_to_range(*spec, v) : v;
}

double factor(TactileParameter p, int step) {
  switch (p) {
    case TactileParameter::period:
    case TactileParameter::frequency: return std::exp2(step / 3.0);
    case TactileParameter::relief:
    case TactileParameter::damping: return std::exp2(step / 2.0);
    case TactileParameter::gain: return std::pow(10.0, 2.0 * step / 20.0);
    case TactileParameter::pattern: return 1.0;
  }
  return 1.0;
}

void visit(std::vector<Element>& elements, const std::function<void(Element&)>& f) {
  for (Element& e : elements) {
    if (auto* g = std::get_if<Group>(&e.body)) {
      visit(g->children, f);
    } else {
      f(e);
    }
  }
}

void visit(const std::vector<Element>& elements, const std::function<void(const Element&)>& f) {
  for (const Element& e : elements) {
    if (const auto* g = std::get_if<Group>(&e.body)) {
      visit(g->children, f);
    } else {
      f(e);
    }
  }
}

std::string element_name(const Element& e) {
  std::string kind = std::holds_alternative<Dot>(e.body) ? "dot" : std::holds_alternative<Line>(e.body) ? "line" : "surface";
  return e.id.empty() ? kind : kind + " '" + e.id + "'";
}

}  // namespace

std::string_view tactile_parameter_name(TactileParameter p) { return kNames[at(p)]; }
std::string_view tactile_parameter_unit(TactileParameter p) { return kUnits[at(p)]; }

std::optional<TactileParameter> parse_tactile_parameter(std::string_view name) {
  for (std::size_t k = 0; k < kTactileParameterCount; ++k)
    if (kNames[k] == name) return static_cast<TactileParameter>(k);
  return std::nullopt;
}

TactileParameterSet all_tactile_parameters() {
  TactileParameterSet s;
  s.fill(true);
  return s;
}

TactileParameterList parse_tactile_parameter_list(std::string_view text) {
  TactileParameterList out;
  std::size_t start = 0;
  bool any = false;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view word = text.substr(start, comma - start);
    start = comma + 1;
    if (word.empty()) continue;
    const auto p = parse_tactile_parameter(word);
    if (!p) {
      out.set = {};
      out.error = "unknown parameter '" + std::string(word) +
                  "' (the tactile parameters: period, relief, pattern, gain, frequency, damping)";
      return out;
    }
    out.set[at(*p)] = true;
    any = true;
  }
  if (!any) out.error = "no parameter named (the tactile parameters: period, relief, pattern, gain, frequency, damping)";
  return out;
}

StepRange step_range(TactileParameter p) { return kSteps[at(p)]; }
bool is_choice_parameter(TactileParameter p) { return p == TactileParameter::pattern; }

TactileParameterSet parameters_present(const Image& image) {
  TactileParameterSet s{};
  visit(image.children, [&](const Element& e) {
    if (std::holds_alternative<Surface>(e.body)) {
      s[at(TactileParameter::period)] = s[at(TactileParameter::relief)] = s[at(TactileParameter::pattern)] = true;
      s[at(TactileParameter::gain)] = true;
    } else if (std::holds_alternative<Line>(e.body)) {
      s[at(TactileParameter::frequency)] = s[at(TactileParameter::damping)] = s[at(TactileParameter::gain)] = true;
    } else if (std::holds_alternative<Dot>(e.body)) {
      s[at(TactileParameter::gain)] = true;
    }
  });
  return s;
}

Image apply_setting(const Image& original, const SeparationSetting& setting) {
  Image image = original;
  const auto step = [&](TactileParameter p) { return static_cast<int>(setting[at(p)]); };
  const double gain = factor(TactileParameter::gain, step(TactileParameter::gain));
  visit(image.children, [&](Element& e) {
    if (auto* s = std::get_if<Surface>(&e.body)) {
      if (step(TactileParameter::period) != 0)
        s->period_mm = scaled(s->period_mm, factor(TactileParameter::period, step(TactileParameter::period)),
                              ParameterOwner::surface, "period");
      if (step(TactileParameter::relief) != 0)
        s->relief_mm = scaled(s->relief_mm, factor(TactileParameter::relief, step(TactileParameter::relief)),
                              ParameterOwner::surface, "relief");
      const int pattern = step(TactileParameter::pattern);
      if (pattern >= 1 && pattern <= 3) s->pattern = kPatterns[static_cast<std::size_t>(pattern - 1)];
      if (step(TactileParameter::gain) != 0) s->gain = scaled(s->gain, gain, ParameterOwner::surface, "gain");
    } else if (auto* l = std::get_if<Line>(&e.body)) {
      if (step(TactileParameter::frequency) != 0)
        l->frequency_hz = scaled(l->frequency_hz, factor(TactileParameter::frequency, step(TactileParameter::frequency)),
                                 ParameterOwner::line, "frequency");
      if (step(TactileParameter::damping) != 0)
        l->damping = scaled(l->damping, factor(TactileParameter::damping, step(TactileParameter::damping)),
                            ParameterOwner::line, "damping");
      if (step(TactileParameter::gain) != 0) l->gain = scaled(l->gain, gain, ParameterOwner::line, "gain");
    } else if (auto* d = std::get_if<Dot>(&e.body)) {
      if (step(TactileParameter::gain) != 0) d->gain = scaled(d->gain, gain, ParameterOwner::dot, "gain");
    }
  });
  return image;
}

std::string tactile_key(const Image& image) {
  std::string key;
  visit(image.children, [&](const Element& e) {
    if (const auto* s = std::get_if<Surface>(&e.body)) {
      key += "s" + format_decimal(s->period_mm) + "," + format_decimal(s->relief_mm) + "," +
             std::string(pattern_name(s->pattern)) + "," + format_decimal(s->gain) + ";";
    } else if (const auto* l = std::get_if<Line>(&e.body)) {
      key += "l" + format_decimal(l->frequency_hz) + "," + format_decimal(l->damping) + "," + format_decimal(l->gain) + ";";
    } else if (const auto* d = std::get_if<Dot>(&e.body)) {
      key += "d" + format_decimal(d->gain) + ";";
    }
  });
  return key;
}

std::vector<ParameterChange> list_changes(const Image& original, const Image& proposal) {
  std::vector<const Element*> before, after;
  // The primitives in paint order (what apply_change counts).
  visit(original.children, [&](const Element& e) {
    if (!std::holds_alternative<UnknownElement>(e.body)) before.push_back(&e);
  });
  visit(proposal.children, [&](const Element& e) {
    if (!std::holds_alternative<UnknownElement>(e.body)) after.push_back(&e);
  });
  std::vector<ParameterChange> out;
  for (std::size_t k = 0; k < before.size() && k < after.size(); ++k) {
    const Element& a = *before[k];
    const Element& b = *after[k];
    const auto add = [&](TactileParameter p, double from, double to) {
      if (from == to) return;
      ParameterChange c{element_name(a), a.id, k, p, format_decimal(from), format_decimal(to), to, {}};
      const std::string unit(tactile_parameter_unit(p));
      c.text = c.element + ": " + std::string(tactile_parameter_name(p)) + " " + c.from + " \u2192 " + c.to +
               (unit.empty() ? "" : " " + unit);
      out.push_back(std::move(c));
    };
    if (const auto* s = std::get_if<Surface>(&a.body)) {
      const auto& t = std::get<Surface>(b.body);
      add(TactileParameter::period, s->period_mm, t.period_mm);
      add(TactileParameter::relief, s->relief_mm, t.relief_mm);
      if (s->pattern != t.pattern) {
        ParameterChange c{element_name(a), a.id, k, TactileParameter::pattern, std::string(pattern_name(s->pattern)),
                          std::string(pattern_name(t.pattern)), static_cast<double>(t.pattern), {}};
        c.text = c.element + ": pattern " + c.from + " \u2192 " + c.to;
        out.push_back(std::move(c));
      }
      add(TactileParameter::gain, s->gain, t.gain);
    } else if (const auto* l = std::get_if<Line>(&a.body)) {
      const auto& t = std::get<Line>(b.body);
      add(TactileParameter::frequency, l->frequency_hz, t.frequency_hz);
      add(TactileParameter::damping, l->damping, t.damping);
      add(TactileParameter::gain, l->gain, t.gain);
    } else if (const auto* d = std::get_if<Dot>(&a.body)) {
      add(TactileParameter::gain, d->gain, std::get<Dot>(b.body).gain);
    }
  }
  return out;
}

Image apply_change(const Image& image, const ParameterChange& change) {
  Image out = image;
  std::size_t k = 0;
  visit(out.children, [&](Element& e) {
    if (std::holds_alternative<UnknownElement>(e.body)) return;
    if (k++ != change.primitive) return;
    const double v = change.to_value;
    if (auto* s = std::get_if<Surface>(&e.body)) {
      switch (change.parameter) {
        case TactileParameter::period: s->period_mm = v; break;
        case TactileParameter::relief: s->relief_mm = v; break;
        case TactileParameter::pattern: s->pattern = static_cast<SurfacePattern>(static_cast<int>(v)); break;
        case TactileParameter::gain: s->gain = v; break;
        default: break;
      }
    } else if (auto* l = std::get_if<Line>(&e.body)) {
      if (change.parameter == TactileParameter::frequency) l->frequency_hz = v;
      if (change.parameter == TactileParameter::damping) l->damping = v;
      if (change.parameter == TactileParameter::gain) l->gain = v;
    } else if (auto* d = std::get_if<Dot>(&e.body)) {
      if (change.parameter == TactileParameter::gain) d->gain = v;
    }
  });
  return out;
}

}  // namespace vimg::study
