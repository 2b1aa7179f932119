#include "study/fit_nelder_mead.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>

namespace vimg::study {

namespace {

class Search {
 public:
  Search(const Objective& f, const std::vector<double>& lower, const std::vector<double>& upper, const NelderMeadOptions& o)
      : f_(f), lower_(lower), upper_(upper), options_(o) {}

  std::vector<double> clamp(std::vector<double> x) const {
    for (std::size_t k = 0; k < x.size(); ++k) x[k] = std::clamp(x[k], lower_[k], upper_[k]);
    return x;
  }

  double value(const std::vector<double>& x) {
    ++evaluations_;
    const double v = f_(x);
    return std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
  }

  bool budget_left() const { return evaluations_ < options_.max_evaluations; }
  int evaluations() const { return evaluations_; }

  // One simplex run from `start` (inside the box); returns the best vertex and its value.
  std::pair<std::vector<double>, double> run(const std::vector<double>& start) {
    const std::size_t n = start.size();
    std::vector<std::vector<double>> vertex{start};
    for (std::size_t k = 0; k < n; ++k) {
      std::vector<double> v = start;
      const double room_up = upper_[k] - start[k], room_down = start[k] - lower_[k];
      v[k] += room_up >= room_down ? std::min(options_.initial_step, room_up) : -std::min(options_.initial_step, room_down);
      vertex.push_back(v);
    }
    std::vector<double> fv;
    for (const auto& v : vertex) fv.push_back(value(v));
    std::vector<std::size_t> order(n + 1);
    while (budget_left()) {
      std::iota(order.begin(), order.end(), std::size_t{0});
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return fv[a] < fv[b]; });
      const std::size_t best = order.front(), worst = order.back(), second = order[n - 1];
      if (!(std::abs(fv[worst] - fv[best]) > options_.tolerance)) break;
      std::vector<double> centroid(n, 0.0);
      for (std::size_t v = 0; v <= n; ++v) {
        if (v == worst) continue;
        for (std::size_t k = 0; k < n; ++k) centroid[k] += vertex[v][k] / static_cast<double>(n);
      }
      const auto along = [&](double t) {
        std::vector<double> p(n);
        for (std::size_t k = 0; k < n; ++k) p[k] = centroid[k] + t * (vertex[worst][k] - centroid[k]);
        return clamp(std::move(p));
      };
      const std::vector<double> reflected = along(-1.0);
      const double fr = value(reflected);
      if (fr < fv[best]) {
        const std::vector<double> expanded = along(-2.0);
        const double fe = value(expanded);
        if (fe < fr) {
          vertex[worst] = expanded, fv[worst] = fe;
        } else {
          vertex[worst] = reflected, fv[worst] = fr;
        }
        continue;
      }
      if (fr < fv[second]) {
        vertex[worst] = reflected, fv[worst] = fr;
        continue;
      }
      const bool outside = fr < fv[worst];
      const std::vector<double> contracted = along(outside ? -0.5 : 0.5);
      const double fc = value(contracted);
      if (fc < (outside ? fr : fv[worst])) {
        vertex[worst] = contracted, fv[worst] = fc;
        continue;
      }
      for (std::size_t v = 0; v <= n; ++v) {  // shrink towards the best vertex
        if (v == best) continue;
        for (std::size_t k = 0; k < n; ++k) vertex[v][k] = vertex[best][k] + 0.5 * (vertex[v][k] - vertex[best][k]);
        fv[v] = value(vertex[v]);
      }
    }
    const std::size_t best = static_cast<std::size_t>(std::min_element(fv.begin(), fv.end()) - fv.begin());
    return {vertex[best], fv[best]};
  }

 private:
  const Objective& f_;
  const std::vector<double>& lower_;
  const std::vector<double>& upper_;
  NelderMeadOptions options_;
  int evaluations_ = 0;
};

}  // namespace

NelderMeadResult minimise_nelder_mead(const Objective& objective, std::vector<double> start, const std::vector<double>& lower,
                                      const std::vector<double>& upper, const NelderMeadOptions& options) {
  Search search(objective, lower, upper, options);
  NelderMeadResult r;
  r.x = search.clamp(std::move(start));
  r.value = search.value(r.x);
  if (r.x.empty()) {
    r.evaluations = search.evaluations();
    return r;
  }
  for (int restart = 0; restart <= options.max_restarts && search.budget_left(); ++restart) {
    auto [x, v] = search.run(r.x);
    const double gain = r.value - v;
    if (v < r.value) r.x = std::move(x), r.value = v;
    if (restart > 0 && !(gain > options.tolerance)) break;
  }
  r.evaluations = search.evaluations();
  return r;
}

}  // namespace vimg::study
