#include "study/report_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "study/report_tables.hpp"

namespace vimg::study {

namespace {

constexpr double kCellPx = 46.0;
constexpr double kCharPx = 7.0;  // average width of a 12 px sans-serif character
constexpr std::size_t kMaxLabelChars = 24;

std::string px(double value) { return fixed_text(value, 1); }

// A label of at most kMaxLabelChars characters (code points), with an ellipsis when cut.
std::string short_label(const std::string& label) {
  std::size_t chars = 0;
  for (std::size_t i = 0; i < label.size(); ++i) {
    if ((static_cast<unsigned char>(label[i]) & 0xC0) == 0x80) continue;  // a UTF-8 continuation byte
    if (++chars > kMaxLabelChars) return label.substr(0, i) + "\u2026";
  }
  return label;
}

// White to a dark blue; the text on it turns white past the middle.
std::string shade_colour(double shade) {
  const double s = std::clamp(shade, 0.0, 1.0);
  const auto channel = [&](double dark) { return static_cast<int>(std::lround(255.0 + (dark - 255.0) * s)); };
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", channel(8.0), channel(48.0), channel(107.0));
  return buffer;
}

std::string text_element(double x, double y, const std::string& text, const std::string& attributes = "") {
  return "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\"" + (attributes.empty() ? "" : " " + attributes) + ">" + xml_text(text) +
         "</text>";
}

}  // namespace

std::string xml_text(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
          out += "\uFFFD";
        } else {
          out += c;
        }
    }
  }
  return out;
}

std::string heat_map_svg(const HeatMap& map) {
  const std::size_t n = map.labels.size();
  std::size_t longest = 1;
  std::vector<std::string> labels;
  for (const std::string& label : map.labels) {
    labels.push_back(short_label(label));
    longest = std::max(longest, std::min(label.size(), kMaxLabelChars + 1));
  }
  const double label_px = kCharPx * static_cast<double>(longest);
  const double left = 30.0 + label_px + 8.0;
  const double top = 40.0 + label_px * 0.72 + 8.0;
  const double grid = kCellPx * static_cast<double>(n);
  // The column labels run up and to the right at 45 degrees from their cells: the last one reaches
  // label_px * cos 45 beyond the grid.
  const double width = std::max(left + grid + label_px * 0.72 + 12.0, 20.0 + kCharPx * static_cast<double>(map.title.size()));
  const double height = top + grid + 12.0;
  std::string s = "<svg role=\"img\" width=\"" + px(width) + "\" height=\"" + px(height) +
                  "\" viewBox=\"0 0 " + px(width) + " " + px(height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s += "<title>" + xml_text(map.title) + "</title>\n";
  s += text_element(8.0, 18.0, map.title, "font-weight=\"bold\"") + "\n";
  s += text_element(left + grid / 2.0, 34.0, "chosen", "text-anchor=\"middle\" font-style=\"italic\"") + "\n";
  s += "<text transform=\"translate(14," + px(top + grid / 2.0) +
       ") rotate(-90)\" text-anchor=\"middle\" font-style=\"italic\">presented</text>\n";
  for (std::size_t j = 0; j < n; ++j) {
    const double x = left + kCellPx * (static_cast<double>(j) + 0.5);
    s += "<text transform=\"translate(" + px(x) + "," + px(top - 6.0) + ") rotate(-45)\">" + xml_text(labels[j]) + "</text>\n";
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double y = top + kCellPx * static_cast<double>(i);
    s += text_element(left - 6.0, y + kCellPx / 2.0 + 4.0, labels[i], "text-anchor=\"end\"") + "\n";
    for (std::size_t j = 0; j < n; ++j) {
      const double x = left + kCellPx * static_cast<double>(j);
      // A plain value and a flag (not a copied std::optional): g++ 12 at -O3 reports a false
      // -Wmaybe-uninitialized on the optional's copy.
      const bool has_shade = i < map.shade.size() && j < map.shade[i].size() && map.shade[i][j].has_value();
      const double shade = has_shade ? *map.shade[i][j] : 0.0;
      s += "<rect x=\"" + px(x) + "\" y=\"" + px(y) + "\" width=\"" + px(kCellPx) + "\" height=\"" + px(kCellPx) + "\" fill=\"" +
           (has_shade ? shade_colour(shade) : std::string("#dddddd")) + "\" stroke=\"#888888\" stroke-width=\"0.5\"/>\n";
      const std::string cell = i < map.cells.size() && j < map.cells[i].size() ? map.cells[i][j] : "";
      const std::string colour = has_shade && shade > 0.5 ? "#ffffff" : "#000000";
      s += text_element(x + kCellPx / 2.0, y + kCellPx / 2.0 + 4.0, cell, "text-anchor=\"middle\" fill=\"" + colour + "\"") + "\n";
    }
  }
  s += "</svg>\n";
  return s;
}

HeatMap comparison_heat_map(const SetReport& set) {
  HeatMap map;
  map.title = "Comparison matrix of set " + set.name + " (counts)";
  map.labels = set.images;
  for (const auto& row : set.comparison) {
    std::size_t total = 0;
    for (const std::size_t c : row) total += c;
    std::vector<std::optional<double>> shade;
    std::vector<std::string> cells;
    for (const std::size_t c : row) {
      shade.push_back(total > 0 ? std::optional(static_cast<double>(c) / static_cast<double>(total)) : std::nullopt);
      cells.push_back(std::to_string(c));
    }
    map.shade.push_back(std::move(shade));
    map.cells.push_back(std::move(cells));
  }
  return map;
}

HeatMap predicted_heat_map(const SetReport& set) {
  HeatMap map;
  map.title = "Predicted confusion of set " + set.name;
  map.labels = set.images;
  if (!set.predicted) return map;
  for (const auto& row : set.predicted->predicted) {
    std::vector<std::optional<double>> shade;
    std::vector<std::string> cells;
    for (const double p : row) {
      shade.push_back(p);
      cells.push_back(fixed_text(p, 2));
    }
    map.shade.push_back(std::move(shade));
    map.cells.push_back(std::move(cells));
  }
  return map;
}

HeatMap measured_heat_map(const SetReport& set) {
  HeatMap map;
  map.title = "Measured confusion of set " + set.name;
  map.labels = set.images;
  if (!set.predicted) return map;
  for (const auto& row : set.predicted->measured) {
    std::vector<std::string> cells;
    for (const std::optional<double>& p : row) cells.push_back(optional_fixed_text(p, 2));
    map.shade.push_back(row);
    map.cells.push_back(std::move(cells));
  }
  return map;
}

std::string location_chart_svg(const LocationReport& location) {
  const double left = 64.0, right = 150.0, top = 44.0, bottom = 64.0, plot_height = 240.0, bar_slot = 120.0;
  const double width = left + bar_slot * static_cast<double>(std::max<std::size_t>(1, location.metaphors.size())) + right;
  const double height = top + plot_height + bottom;
  double highest = std::max(1.0, location.chance_mm);
  for (const MetaphorReport& m : location.metaphors) {
    highest = std::max(highest, m.ci99_mm ? m.ci99_mm->upper : m.mean_mm);
  }
  // Ticks every 1, 2 or 5 times a power of ten, about five of them.
  const double raw_step = highest / 5.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw_step)));
  double step = magnitude;
  for (const double k : {1.0, 2.0, 5.0, 10.0}) {
    if (k * magnitude >= raw_step) {
      step = k * magnitude;
      break;
    }
  }
  const double top_value = step * std::ceil(highest * 1.05 / step);
  const auto y_of = [&](double mm) { return top + plot_height * (1.0 - std::clamp(mm, 0.0, top_value) / top_value); };
  const double axis_right = width - right + 20.0;
  std::string s = "<svg role=\"img\" width=\"" + px(width) + "\" height=\"" + px(height) +
                  "\" viewBox=\"0 0 " + px(width) + " " + px(height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s += "<title>Location error per metaphor: mean and 99 % confidence interval, against chance</title>\n";
  s += text_element(8.0, 18.0, "Location error: mean with its 99 % t interval; dashed: chance", "font-weight=\"bold\"") + "\n";
  s += "<text transform=\"translate(16," + px(top + plot_height / 2.0) + ") rotate(-90)\" text-anchor=\"middle\">error (mm)</text>\n";
  for (double v = 0.0; v <= top_value + step / 2.0; v += step) {
    const double y = y_of(v);
    s += "<line x1=\"" + px(left) + "\" y1=\"" + px(y) + "\" x2=\"" + px(axis_right) + "\" y2=\"" + px(y) +
         "\" stroke=\"#e0e0e0\"/>\n";
    s += text_element(left - 6.0, y + 4.0, fixed_text(v, step < 1.0 ? 1 : 0), "text-anchor=\"end\"") + "\n";
  }
  s += "<line x1=\"" + px(left) + "\" y1=\"" + px(top) + "\" x2=\"" + px(left) + "\" y2=\"" + px(top + plot_height) +
       "\" stroke=\"#000000\"/>\n";
  s += "<line x1=\"" + px(left) + "\" y1=\"" + px(top + plot_height) + "\" x2=\"" + px(axis_right) + "\" y2=\"" +
       px(top + plot_height) + "\" stroke=\"#000000\"/>\n";
  for (std::size_t k = 0; k < location.metaphors.size(); ++k) {
    const MetaphorReport& m = location.metaphors[k];
    const double centre = left + bar_slot * (static_cast<double>(k) + 0.5);
    const double bar_top = y_of(m.mean_mm);
    s += "<rect x=\"" + px(centre - 30.0) + "\" y=\"" + px(bar_top) + "\" width=\"60\" height=\"" +
         px(top + plot_height - bar_top) + "\" fill=\"#6b8fc7\"><title>" + xml_text(m.name) + ": mean " + fixed_text(m.mean_mm, 1) +
         " mm, 99 % CI " + xml_text(interval_text(m.ci99_mm, 1)) + " mm</title></rect>\n";
    if (m.ci99_mm) {
      const double y1 = y_of(m.ci99_mm->lower), y2 = y_of(m.ci99_mm->upper);
      s += "<path d=\"M" + px(centre) + " " + px(y1) + "V" + px(y2) + "M" + px(centre - 10.0) + " " + px(y1) + "H" +
           px(centre + 10.0) + "M" + px(centre - 10.0) + " " + px(y2) + "H" + px(centre + 10.0) +
           "\" stroke=\"#000000\" stroke-width=\"1.5\" fill=\"none\"/>\n";
    }
    s += text_element(centre + 14.0, bar_top - 4.0, fixed_text(m.mean_mm, 1)) + "\n";
    s += text_element(centre, top + plot_height + 18.0, m.name, "text-anchor=\"middle\"") + "\n";
    s += text_element(centre, top + plot_height + 34.0, "n = " + std::to_string(m.n), "text-anchor=\"middle\"") + "\n";
  }
  const double chance_y = y_of(location.chance_mm);
  s += "<line x1=\"" + px(left) + "\" y1=\"" + px(chance_y) + "\" x2=\"" + px(axis_right) + "\" y2=\"" + px(chance_y) +
       "\" stroke=\"#c0392b\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\"/>\n";
  s += text_element(axis_right + 4.0, chance_y + 4.0, "chance " + fixed_text(location.chance_mm, 1) + " mm", "fill=\"#c0392b\"") + "\n";
  s += "</svg>\n";
  return s;
}

}  // namespace vimg::study
