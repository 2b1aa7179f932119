#include "fixture_signals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "primitives/random/splitmix64.hpp"

namespace vimg::test {

namespace {

constexpr double kFs = 8000.0;

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

double number(const std::string& text) { return std::stod(text); }
std::size_t count(const std::string& text) { return static_cast<std::size_t>(std::stoull(text)); }

std::vector<double> component(const std::string& kind, std::size_t length, const std::vector<std::string>& p) {
  const std::size_t start = count(p.at(0));
  const std::size_t end = std::min(count(p.at(1)), length);
  std::vector<double> out(length, 0.0);
  const double two_pi = 2.0 * std::numbers::pi;
  if (kind == "noise") {
    SplitMix64 random(std::stoull(p.at(2)));
    const double a = number(p.at(3));
    for (std::size_t n = start; n < end; ++n) out[n] = a * (2.0 * random.unit() - 1.0);
    return out;
  }
  for (std::size_t n = start; n < end; ++n) {
    const double t = static_cast<double>(n - start) / kFs;
    if (kind == "sine") {
      const double w = two_pi * number(p.at(2));
      out[n] = number(p.at(3)) * std::sin(w * t + number(p.at(4)));
    } else if (kind == "chirp") {
      const double f0 = number(p.at(2)), f1 = number(p.at(3)), a = number(p.at(4));
      const double duration = static_cast<double>(count(p.at(1)) - start) / kFs;
      out[n] = a * std::sin(two_pi * (f0 * t + (f1 - f0) * t * t / (2.0 * duration)));
    } else if (kind == "pulses") {
      const std::size_t k = (n - start) % count(p.at(2));
      if (k < count(p.at(3))) {
        out[n] = number(p.at(5)) * std::sin(two_pi * number(p.at(4)) * (static_cast<double>(k) / kFs));
      }
    } else if (kind == "ring") {
      const double tk = static_cast<double>((n - start) % count(p.at(2))) / kFs;
      out[n] = number(p.at(4)) * std::exp(-tk / number(p.at(5))) * std::sin(two_pi * number(p.at(3)) * tk);
    } else if (kind == "const") {
      out[n] = number(p.at(2));
    } else {
      throw std::runtime_error("unknown component " + kind);
    }
  }
  return out;
}

}  // namespace

std::vector<double> make_fixture_signal(std::size_t samples, const std::string& recipe) {
  std::vector<double> signal(samples, 0.0);
  std::istringstream items(recipe);
  std::string item;
  while (items >> item) {
    std::vector<std::string> parts = split(item, ':');
    const std::string kind = parts.front();
    parts.erase(parts.begin());
    if (kind == "gain") {
      const double g = number(parts.at(0));
      for (double& x : signal) x = g * x;
    } else if (kind == "delay") {
      const std::size_t d = std::min(count(parts.at(0)), samples);
      signal.insert(signal.begin(), d, 0.0);
      signal.resize(samples);
    } else if (kind == "clip") {
      const double c = number(parts.at(0));
      for (double& x : signal) x = std::min(std::max(x, -c), c);
    } else {
      const std::vector<double> values = component(kind, samples, parts);
      for (std::size_t n = 0; n < samples; ++n) signal[n] = signal[n] + values[n];
    }
  }
  return signal;
}

std::vector<std::map<std::string, std::string>> read_csv_rows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string> cells = split(line, ',');
    if (header.empty()) {
      header = cells;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size(); ++i) row[header[i]] = i < cells.size() ? cells[i] : "";
    rows.push_back(row);
  }
  return rows;
}

std::map<std::string, std::vector<double>> load_fixture_signals(const std::string& signals_csv) {
  std::map<std::string, std::vector<double>> signals;
  for (const auto& row : read_csv_rows(signals_csv)) {
    signals[row.at("name")] = make_fixture_signal(count(row.at("samples")), row.at("recipe"));
  }
  return signals;
}

}  // namespace vimg::test
