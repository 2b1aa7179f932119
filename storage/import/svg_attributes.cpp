#include "storage/import/svg_attributes.hpp"

#include <algorithm>
#include <cmath>

#include "storage/import/svg_path.hpp"

namespace vimg::svg {

namespace {

bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

std::string_view trim(std::string_view t) {
  while (!t.empty() && is_wsp(t.front())) t.remove_prefix(1);
  while (!t.empty() && is_wsp(t.back())) t.remove_suffix(1);
  return t;
}

bool starts_with(std::string_view t, std::string_view prefix) { return t.substr(0, prefix.size()) == prefix; }

}  // namespace

std::optional<Length> parse_length(std::string_view text) {
  text = trim(text);
  std::size_t pos = 0;
  Length l;
  if (!scan_number(text, pos, l.value, false)) return std::nullopt;
  const std::string_view unit = text.substr(pos);
  using U = Length::Unit;
  static constexpr std::pair<std::string_view, U> kUnits[] = {{"", U::none}, {"px", U::px}, {"mm", U::mm},
                                                              {"cm", U::cm}, {"in", U::in}, {"pt", U::pt},
                                                              {"pc", U::pc}, {"%", U::percent}, {"em", U::em},
                                                              {"ex", U::ex}};
  for (const auto& [name, u] : kUnits) {
    if (unit == name) {
      l.unit = u;
      return l;
    }
  }
  return std::nullopt;
}

std::optional<double> length_user(const Length& l) {
  using U = Length::Unit;
  switch (l.unit) {
    case U::none:
    case U::px: return l.value;
    case U::mm: return l.value * kPxPerInch / kMmPerInch;
    case U::cm: return l.value * 10.0 * kPxPerInch / kMmPerInch;
    case U::in: return l.value * kPxPerInch;
    case U::pt: return l.value * kPxPerInch / 72.0;
    case U::pc: return l.value * kPxPerInch / 6.0;
    default: return std::nullopt;
  }
}

std::optional<double> length_mm(const Length& l) {
  const std::optional<double> px = length_user(l);
  if (!px) return std::nullopt;
  return *px * kMmPerInch / kPxPerInch;
}

std::optional<ViewBox> parse_view_box(std::string_view text) {
  double v[4];
  std::size_t pos = 0;
  for (int i = 0; i < 4; ++i) {
    if (!scan_number(text, pos, v[i], i > 0)) return std::nullopt;
  }
  if (!trim(text.substr(pos)).empty()) return std::nullopt;
  return ViewBox{v[0], v[1], v[2], v[3]};
}

std::optional<Affine> view_box_transform(const ViewBox& box, double width, double height, std::string_view par) {
  par = trim(par);
  if (starts_with(par, "defer")) par = trim(par.substr(5));
  std::string_view align = par.substr(0, std::min(par.find_first_of(" \t\r\n"), par.size()));
  std::string_view mode = trim(par.substr(align.size()));
  if (align.empty()) align = "xMidYMid";
  if (mode.empty()) mode = "meet";
  if (mode != "meet" && mode != "slice") return std::nullopt;
  const double sx = width / box.width, sy = height / box.height;
  if (align == "none") return Affine{sx, 0, 0, sy, -box.x * sx, -box.y * sy};
  if (align.size() != 8 || align[0] != 'x' || align[4] != 'Y') return std::nullopt;
  const auto where = [](std::string_view part) -> std::optional<double> {
    if (part == "Min") return 0.0;
    if (part == "Mid") return 0.5;
    if (part == "Max") return 1.0;
    return std::nullopt;
  };
  const auto fx = where(align.substr(1, 3)), fy = where(align.substr(5, 3));
  if (!fx || !fy) return std::nullopt;
  const double s = mode == "meet" ? std::min(sx, sy) : std::max(sx, sy);
  return Affine{s, 0, 0, s, -box.x * s + (width - box.width * s) * *fx, -box.y * s + (height - box.height * s) * *fy};
}

std::optional<std::string> DeclaredProperties::get(std::string_view name) const {
  // The last declaration wins (style after presentation attributes).
  for (auto it = values.rbegin(); it != values.rend(); ++it) {
    if (it->first == name) return it->second;
  }
  return std::nullopt;
}

DeclaredProperties declared_properties(const std::vector<std::pair<std::string, std::string>>& attributes,
                                       std::string_view style) {
  DeclaredProperties out;
  for (const auto& [name, value] : attributes) out.values.emplace_back(name, std::string(trim(value)));
  while (!style.empty()) {
    const std::size_t semi = std::min(style.find(';'), style.size());
    const std::string_view declaration = style.substr(0, semi);
    style.remove_prefix(std::min(semi + 1, style.size()));
    const std::size_t colon = declaration.find(':');
    if (colon == std::string_view::npos) continue;
    std::string_view value = trim(declaration.substr(colon + 1));
    if (const std::size_t bang = value.find("!important"); bang != std::string_view::npos) value = trim(value.substr(0, bang));
    out.values.emplace_back(std::string(trim(declaration.substr(0, colon))), std::string(value));
  }
  return out;
}

namespace {

// none / a colour / url(...) [fallback]; sets painted and server.
void paint(std::string_view value, bool parent_painted, bool parent_server, bool& painted, bool& server) {
  if (value == "inherit") {
    painted = parent_painted;
    server = parent_server;
  } else if (value == "none" || value == "transparent") {
    painted = false;
    server = false;
  } else if (starts_with(value, "url(")) {
    painted = true;  // a fallback of "none" after the url still paints with the server
    server = true;
  } else {
    painted = true;  // any colour: the shape is drawn (its colour is not imported)
    server = false;
  }
}

bool zero_opacity(const std::optional<std::string>& value) {
  if (!value) return false;
  std::size_t pos = 0;
  double v = 1.0;
  return scan_number(*value, pos, v, false) && v <= 0.0;
}

}  // namespace

Style cascade(const Style& parent, const DeclaredProperties& d, std::vector<std::string>& problems) {
  Style s = parent;
  s.displayed = true;  // display is not inherited; a hidden parent hides the subtree by the walk
  if (auto v = d.get("fill")) paint(*v, parent.fill, parent.fill_is_server, s.fill, s.fill_is_server);
  if (auto v = d.get("stroke")) paint(*v, parent.stroke, parent.stroke_is_server, s.stroke, s.stroke_is_server);
  if (zero_opacity(d.get("fill-opacity"))) s.fill = false;
  if (zero_opacity(d.get("stroke-opacity"))) s.stroke = false;
  if (zero_opacity(d.get("opacity"))) s.fill = s.stroke = false;
  if (auto v = d.get("stroke-width"); v && *v != "inherit") {
    const std::optional<Length> l = parse_length(*v);
    const std::optional<double> user = l ? length_user(*l) : std::nullopt;
    if (user && *user >= 0.0) {
      s.stroke_width = *user;
    } else {
      problems.push_back("stroke-width '" + *v + "' is not a length in absolute units; the inherited width is used");
    }
  }
  if (auto v = d.get("fill-rule"); v && *v != "inherit") s.even_odd = *v == "evenodd";
  if (auto v = d.get("display")) s.displayed = *v != "none";
  if (auto v = d.get("visibility"); v && *v != "inherit") s.visible = *v == "visible";
  if (auto v = d.get("stroke-dasharray"); v && *v != "inherit") s.dashed = *v != "none";
  return s;
}

}  // namespace vimg::svg
