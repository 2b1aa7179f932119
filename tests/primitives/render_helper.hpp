#pragma once
// Test helpers: drive a shader along a path at an output sample rate and measure the result.
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

#include "primitives/shader.hpp"

namespace vimg::test {

struct PathPoint {
  Vec3 position_m;
  Vec3 velocity_m_per_s;
  double pressure = 1.0;
};
using Path = std::function<PathPoint(double time_s)>;

// Straight motion from start at a constant velocity.
inline Path straight_path(const Vec3& start_m, const Vec3& velocity_m_per_s) {
  return [=](double t) { return PathPoint{start_m + velocity_m_per_s * t, velocity_m_per_s, 1.0}; };
}

struct Rendered {
  std::vector<double> time_s;
  std::vector<double> drive;   // force along the axis / full scale
  std::vector<bool> active;    // shader.active() after each sample
  double sample_rate_hz = 0.0;
};

// Begins one contact at t = 0 and evaluates the shader at t = k / rate, k = 1..duration * rate.
inline Rendered render(const ForceShader& shader, const Path& path, double duration_s, double rate_hz = 8000.0,
                       const Vec3& axis = {0, 0, 1}, double full_scale_force_N = 1.0) {
  Rendered out;
  out.sample_rate_hz = rate_hz;
  ShaderState state;
  shader.begin_contact(state);
  const double dt = 1.0 / rate_hz;
  const auto samples = static_cast<std::size_t>(std::llround(duration_s * rate_hz));
  PathPoint previous = path(0.0);
  for (std::size_t k = 1; k <= samples; ++k) {
    const double t = static_cast<double>(k) * dt;
    const PathPoint now = path(t);
    InteractionState s;
    s.previous_position_m = previous.position_m;
    s.position_m = now.position_m;
    s.velocity_m_per_s = now.velocity_m_per_s;
    s.pressure = now.pressure;
    s.time_s = t;
    s.dt_s = dt;
    const Vec3 f = shader.force_N(s, state);
    out.time_s.push_back(t);
    out.drive.push_back(dot(f, axis) / full_scale_force_N);
    out.active.push_back(shader.active(state));
    previous = now;
  }
  return out;
}

// Times of sign changes inside [from, to]: linear interpolation between two adjacent samples of
// opposite signs, or the middle of a run of at most two exact zeros between opposite signs.
// Longer silences are gaps, not crossings.
inline std::vector<double> zero_crossings(const Rendered& r, double from_s, double to_s) {
  std::vector<double> out;
  std::size_t last_nonzero = r.drive.size();
  for (std::size_t k = 0; k < r.drive.size(); ++k) {
    if (r.time_s[k] < from_s || r.time_s[k] > to_s) {
      last_nonzero = r.drive.size();
      continue;
    }
    const double b = r.drive[k];
    if (b == 0.0) continue;
    if (last_nonzero < r.drive.size() && k - last_nonzero <= 3) {
      const double a = r.drive[last_nonzero];
      if ((a < 0.0) != (b < 0.0)) {
        if (k - last_nonzero == 1) {
          out.push_back(r.time_s[last_nonzero] + (r.time_s[k] - r.time_s[last_nonzero]) * a / (a - b));
        } else {
          out.push_back(0.5 * (r.time_s[last_nonzero + 1] + r.time_s[k - 1]));
        }
      }
    }
    last_nonzero = k;
  }
  return out;
}

// Frequency from the first and last of at least three zero crossings (two per period).
inline double crossing_frequency_hz(const std::vector<double>& crossings) {
  if (crossings.size() < 3) return 0.0;
  return 0.5 * static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
}

struct Peak {
  double time_s;
  double value;
};

// Local maxima of |drive| in [from, to], refined by a parabola through three samples.
inline std::vector<Peak> abs_peaks(const Rendered& r, double from_s, double to_s) {
  std::vector<Peak> out;
  for (std::size_t k = 1; k + 1 < r.drive.size(); ++k) {
    if (r.time_s[k] < from_s || r.time_s[k] > to_s) continue;
    const double a = std::abs(r.drive[k - 1]);
    const double b = std::abs(r.drive[k]);
    const double c = std::abs(r.drive[k + 1]);
    if (b > a && b >= c && b > 0.0) {
      const double denominator = a - 2.0 * b + c;
      const double offset = denominator != 0.0 ? 0.5 * (a - c) / denominator : 0.0;
      const double dt = 1.0 / r.sample_rate_hz;
      out.push_back({r.time_s[k] + offset * dt, b - 0.25 * (a - c) * offset});
    }
  }
  return out;
}

// Least-squares slope of y over x.
inline double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

inline double max_abs(const Rendered& r, double from_s = -1e300, double to_s = 1e300) {
  double m = 0.0;
  for (std::size_t k = 0; k < r.drive.size(); ++k) {
    if (r.time_s[k] >= from_s && r.time_s[k] <= to_s) m = std::max(m, std::abs(r.drive[k]));
  }
  return m;
}

}  // namespace vimg::test
