#include "storage/import/svg_transform.hpp"

#include <cmath>
#include <numbers>

#include "storage/import/svg_path.hpp"

namespace vimg::svg {

double Affine::mean_scale() const { return std::sqrt(std::fabs(determinant())); }

bool Affine::similarity() const {
  const double tolerance = 1e-9 * (std::fabs(a) + std::fabs(b) + std::fabs(c) + std::fabs(d));
  return (std::fabs(a - d) <= tolerance && std::fabs(b + c) <= tolerance) ||
         (std::fabs(a + d) <= tolerance && std::fabs(b - c) <= tolerance);
}

bool Affine::finite() const {
  return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d) && std::isfinite(e) &&
         std::isfinite(f);
}

namespace {

bool is_wsp(char ch) { return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\f'; }

void skip_wsp_commas(std::string_view t, std::size_t& pos) {
  while (pos < t.size() && (is_wsp(t[pos]) || t[pos] == ',')) ++pos;
}

}  // namespace

TransformParse parse_transform(std::string_view t) {
  TransformParse out;
  std::size_t pos = 0;
  while (true) {
    skip_wsp_commas(t, pos);
    if (pos >= t.size()) return out;
    const std::size_t name_begin = pos;
    while (pos < t.size() && ((t[pos] >= 'a' && t[pos] <= 'z') || (t[pos] >= 'A' && t[pos] <= 'Z'))) ++pos;
    const std::string_view name = t.substr(name_begin, pos - name_begin);
    while (pos < t.size() && is_wsp(t[pos])) ++pos;
    if (pos >= t.size() || t[pos] != '(') {
      out.error = "'(' expected after '" + std::string(name) + "'";
      return out;
    }
    ++pos;
    double v[6] = {};
    int n = 0;
    double value = 0.0;
    while (n < 6 && scan_number(t, pos, value, n > 0)) v[n++] = value;
    while (pos < t.size() && is_wsp(t[pos])) ++pos;
    if (pos >= t.size() || t[pos] != ')') {
      out.error = "')' expected to close '" + std::string(name) + "('";
      return out;
    }
    ++pos;
    Affine m;
    const double deg = std::numbers::pi / 180.0;
    if (name == "matrix" && n == 6) {
      m = {v[0], v[1], v[2], v[3], v[4], v[5]};
    } else if (name == "translate" && (n == 1 || n == 2)) {
      m.e = v[0];
      m.f = n == 2 ? v[1] : 0.0;
    } else if (name == "scale" && (n == 1 || n == 2)) {
      m.a = v[0];
      m.d = n == 2 ? v[1] : v[0];
    } else if (name == "rotate" && (n == 1 || n == 3)) {
      const double cs = std::cos(v[0] * deg), sn = std::sin(v[0] * deg);
      m = {cs, sn, -sn, cs, 0.0, 0.0};
      if (n == 3) m = Affine{1, 0, 0, 1, v[1], v[2]} * m * Affine{1, 0, 0, 1, -v[1], -v[2]};
    } else if (name == "skewX" && n == 1) {
      m.c = std::tan(v[0] * deg);
    } else if (name == "skewY" && n == 1) {
      m.b = std::tan(v[0] * deg);
    } else {
      out.error = "'" + std::string(name) + "' with " + std::to_string(n) + " numbers is not a transform";
      return out;
    }
    out.transform = out.transform * m;
    if (!out.transform.finite()) {
      out.error = "the transform is not finite";
      return out;
    }
  }
}

}  // namespace vimg::svg
