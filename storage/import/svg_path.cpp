#include "storage/import/svg_path.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

namespace vimg::svg {

namespace {

bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

void skip_wsp(std::string_view t, std::size_t& pos) {
  while (pos < t.size() && is_wsp(t[pos])) ++pos;
}

}  // namespace

void skip_comma_wsp(std::string_view t, std::size_t& pos) {
  skip_wsp(t, pos);
  if (pos < t.size() && t[pos] == ',') {
    ++pos;
    skip_wsp(t, pos);
  }
}

bool scan_number(std::string_view t, std::size_t& pos, double& value, bool allow_comma) {
  std::size_t p = pos;
  if (allow_comma) {
    skip_comma_wsp(t, p);
  } else {
    skip_wsp(t, p);
  }
  const std::size_t begin = p;
  if (p < t.size() && (t[p] == '+' || t[p] == '-')) ++p;
  const std::size_t digits_begin = p;
  std::size_t digits = 0;
  while (p < t.size() && is_digit(t[p])) ++p, ++digits;
  if (p < t.size() && t[p] == '.') {
    ++p;
    while (p < t.size() && is_digit(t[p])) ++p, ++digits;
  }
  if (digits == 0) return false;
  if (p < t.size() && (t[p] == 'e' || t[p] == 'E')) {
    std::size_t q = p + 1;
    if (q < t.size() && (t[q] == '+' || t[q] == '-')) ++q;
    if (q < t.size() && is_digit(t[q])) {
      while (q < t.size() && is_digit(t[q])) ++q;
      p = q;
    }
  }
  // from_chars does not take '+'; the sign is applied here.
  const bool negative = t[begin] == '-';
  double magnitude = 0.0;
  const char* first = t.data() + digits_begin;
  const char* last = t.data() + p;
  const auto [end, ec] = std::from_chars(first, last, magnitude, std::chars_format::general);
  if (ec != std::errc{} || end != last || !std::isfinite(magnitude)) return false;
  value = negative ? -magnitude : magnitude;
  pos = p;
  return true;
}

namespace {

struct Parser {
  std::string_view d;
  std::size_t max_segments = 0;
  std::size_t pos = 0;
  std::size_t segment_count = 0;
  PathParse out;
  Vec2 current;
  Vec2 subpath_start;
  Vec2 last_cubic_c2;  // for S: the reflection point
  Vec2 last_quad_c;    // for T
  char previous = 0;   // previous command, upper case

  bool fail(std::string message) {
    out.error = std::move(message);
    out.error_offset = pos;
    return false;
  }

  Subpath& subpath() {
    if (out.subpaths.empty() || out.subpaths.back().closed) {
      // Drawing after Z without M starts a new subpath at the closed one's start.
      out.subpaths.push_back(Subpath{current, {}, false});
    }
    return out.subpaths.back();
  }

  bool add(const PathSegment& s) {
    if (++segment_count > max_segments) {
      return fail("more than " + std::to_string(max_segments) + " segments in one path (limit " +
                  std::to_string(max_segments) + ")");
    }
    subpath().segments.push_back(s);
    current = s.end;
    return true;
  }

  bool line_to(Vec2 p) { return add({PathSegment::Kind::line, {}, {}, p}); }
  bool cubic_to(Vec2 c1, Vec2 c2, Vec2 p) { return add({PathSegment::Kind::cubic, c1, c2, p}); }

  bool number(double& v) {
    if (!scan_number(d, pos, v, true)) {
      skip_comma_wsp(d, pos);
      return fail("a number was expected");
    }
    return true;
  }

  bool flag(bool& f) {
    skip_comma_wsp(d, pos);
    if (pos < d.size() && (d[pos] == '0' || d[pos] == '1')) {
      f = d[pos] == '1';
      ++pos;
      return true;
    }
    return fail("an arc flag (0 or 1) was expected");
  }

  // Does another argument group follow (an implicit repeat of the command)?
  bool more_numbers() {
    std::size_t p = pos;
    skip_comma_wsp(d, p);
    if (p >= d.size()) return false;
    const char c = d[p];
    return is_digit(c) || c == '.' || c == '-' || c == '+';
  }

  bool arc_to(double rx, double ry, double angle_deg, bool large, bool sweep, Vec2 p) {
    const Vec2 p0 = current;
    if (p0 == p) return true;  // SVG: an arc to the current point is omitted
    rx = std::fabs(rx);
    ry = std::fabs(ry);
    if (rx == 0.0 || ry == 0.0) return line_to(p);
    const double phi = angle_deg * std::numbers::pi / 180.0;
    const double cs = std::cos(phi), sn = std::sin(phi);
    const double dx = (p0.x - p.x) / 2.0, dy = (p0.y - p.y) / 2.0;
    const double x1 = cs * dx + sn * dy, y1 = -sn * dx + cs * dy;
    const double lambda = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
    if (lambda > 1.0) {
      rx *= std::sqrt(lambda);
      ry *= std::sqrt(lambda);
    }
    const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
    const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    double coef = den > 0.0 ? std::sqrt(std::max(0.0, num / den)) : 0.0;
    if (large == sweep) coef = -coef;
    const double cxp = coef * rx * y1 / ry, cyp = -coef * ry * x1 / rx;
    const double cx = cs * cxp - sn * cyp + (p0.x + p.x) / 2.0;
    const double cy = sn * cxp + cs * cyp + (p0.y + p.y) / 2.0;
    const auto angle = [](double ux, double uy, double vx, double vy) { return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy); };
    const double theta1 = angle(1.0, 0.0, (x1 - cxp) / rx, (y1 - cyp) / ry);
    double delta = angle((x1 - cxp) / rx, (y1 - cyp) / ry, (-x1 - cxp) / rx, (-y1 - cyp) / ry);
    if (!sweep && delta > 0.0) delta -= 2.0 * std::numbers::pi;
    if (sweep && delta < 0.0) delta += 2.0 * std::numbers::pi;
    if (!std::isfinite(delta) || !std::isfinite(cx) || !std::isfinite(cy)) return line_to(p);
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::fabs(delta) / (std::numbers::pi / 4.0) - 1e-9)));
    const double step = delta / pieces;
    const double k = 4.0 / 3.0 * std::tan(step / 4.0);
    const auto on_ellipse = [&](double t) {
      return Vec2{cx + rx * std::cos(t) * cs - ry * std::sin(t) * sn, cy + rx * std::cos(t) * sn + ry * std::sin(t) * cs};
    };
    const auto derivative = [&](double t) {
      return Vec2{-rx * std::sin(t) * cs - ry * std::cos(t) * sn, -rx * std::sin(t) * sn + ry * std::cos(t) * cs};
    };
    double t = theta1;
    for (int i = 0; i < pieces; ++i) {
      const double t2 = t + step;
      const Vec2 a = on_ellipse(t), b = i + 1 == pieces ? p : on_ellipse(t2);
      if (!cubic_to(a + k * derivative(t), b - k * derivative(t2), b)) return false;
      t = t2;
    }
    return true;
  }

  bool command(char cmd) {
    const bool rel = cmd >= 'a' && cmd <= 'z';
    const char up = static_cast<char>(rel ? cmd - 'a' + 'A' : cmd);
    const Vec2 base = rel ? current : Vec2{};
    double x = 0, y = 0, x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    bool ok = true;
    switch (up) {
      case 'M':
        if (!number(x) || !number(y)) return false;
        current = base + Vec2{x, y};
        subpath_start = current;
        out.subpaths.push_back(Subpath{current, {}, false});
        previous = 'M';
        // Further pairs are implicit line-tos (relative after m).
        while (more_numbers()) {
          const Vec2 b = rel ? current : Vec2{};
          if (!number(x) || !number(y) || !line_to(b + Vec2{x, y})) return false;
          previous = 'L';
        }
        return true;
      case 'Z':
        if (!out.subpaths.empty() && !out.subpaths.back().closed) {
          Subpath& s = out.subpaths.back();
          if (!(current == s.start) && !line_to(s.start)) return false;
          out.subpaths.back().closed = true;
        }
        current = subpath_start;
        previous = 'Z';
        return true;
      default:
        break;
    }
    if (out.subpaths.empty()) return fail("path data must begin with a moveto (M or m)");
    do {
      const Vec2 b = rel ? current : Vec2{};
      switch (up) {
        case 'L':
          ok = number(x) && number(y) && line_to(b + Vec2{x, y});
          break;
        case 'H':
          ok = number(x) && line_to({b.x + x, current.y});
          break;
        case 'V':
          ok = number(y) && line_to({current.x, b.y + y});
          break;
        case 'C':
          ok = number(x1) && number(y1) && number(x2) && number(y2) && number(x) && number(y) &&
               cubic_to(b + Vec2{x1, y1}, b + Vec2{x2, y2}, b + Vec2{x, y});
          if (ok) last_cubic_c2 = b + Vec2{x2, y2};
          break;
        case 'S': {
          const Vec2 c1 = (previous == 'C' || previous == 'S') ? current * 2.0 - last_cubic_c2 : current;
          ok = number(x2) && number(y2) && number(x) && number(y) && cubic_to(c1, b + Vec2{x2, y2}, b + Vec2{x, y});
          if (ok) last_cubic_c2 = b + Vec2{x2, y2};
          break;
        }
        case 'Q':
        case 'T': {
          Vec2 q;
          if (up == 'Q') {
            ok = number(x1) && number(y1);
            q = b + Vec2{x1, y1};
          } else {
            q = (previous == 'Q' || previous == 'T') ? current * 2.0 - last_quad_c : current;
          }
          ok = ok && number(x) && number(y);
          if (ok) {
            const Vec2 p0 = current, p = b + Vec2{x, y};
            ok = cubic_to(p0 + (q - p0) * (2.0 / 3.0), p + (q - p) * (2.0 / 3.0), p);
            last_quad_c = q;
          }
          break;
        }
        case 'A': {
          double rx = 0, ry = 0, rot = 0;
          bool large = false, sweep = false;
          ok = number(rx) && number(ry) && number(rot) && flag(large) && flag(sweep) && number(x) && number(y) &&
               arc_to(rx, ry, rot, large, sweep, b + Vec2{x, y});
          break;
        }
        default:
          return fail(std::string("unknown path command '") + cmd + "'");
      }
      if (!ok) return false;
      previous = up;
    } while (more_numbers());
    return true;
  }

  void run() {
    skip_wsp(d, pos);
    if (pos < d.size() && !(d[pos] == 'M' || d[pos] == 'm')) {
      fail("path data must begin with a moveto (M or m)");
      return;
    }
    while (true) {
      skip_wsp(d, pos);
      if (pos >= d.size()) return;
      const char c = d[pos];
      if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) {
        fail("a path command was expected");
        return;
      }
      ++pos;
      if (!command(c)) return;
    }
  }
};

}  // namespace

PathParse parse_path_data(std::string_view d, std::size_t max_segments) {
  Parser p;
  p.d = d;
  p.max_segments = max_segments;
  p.run();
  // A subpath of only a moveto draws nothing.
  std::erase_if(p.out.subpaths, [](const Subpath& s) { return s.segments.empty(); });
  return std::move(p.out);
}

}  // namespace vimg::svg
