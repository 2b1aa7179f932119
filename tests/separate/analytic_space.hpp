#pragma once
// A SeparationSpace whose images are points in the three cues (level, pitch, envelope), in JNDs,
// and whose settings move them by known amounts: period moves pitch by `pitch_per_step` JNDs a
// step, gain moves level by 1 JND a step, each pattern moves envelope to its own place. The
// search's answers can then be checked exactly (exhaustive search over the same steps).
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "study/separate_search.hpp"

namespace vimg::test {

struct AnalyticImage {
  std::array<double, 3> at{};  // level, pitch, envelope (JNDs)
};

class AnalyticSpace final : public study::SeparationSpace {
 public:
  AnalyticSpace(std::vector<AnalyticImage> images, double pitch_per_step = 0.8)
      : images_(std::move(images)), pitch_per_step_(pitch_per_step) {}

  std::size_t image_count() const override { return images_.size(); }
  bool allowed(std::size_t image, const study::SeparationSetting& s) override {
    (void)image;
    return std::abs(s[static_cast<std::size_t>(study::TactileParameter::period)]) <= period_limit;
  }
  double change_jnd(std::size_t image, const study::SeparationSetting& s) override {
    const auto a = place(image, {});
    const auto b = place(image, s);
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  }
  CueDistances cues(std::size_t i, const study::SeparationSetting& a, std::size_t j,
                    const study::SeparationSetting& b) override {
    const auto pa = place(i, a);
    const auto pb = place(j, b);
    return {std::abs(pa[0] - pb[0]), std::abs(pa[1] - pb[1]), std::abs(pa[2] - pb[2])};
  }

  int period_limit = 6;  // steps beyond it are not allowed (a band edge)

 private:
  std::array<double, 3> place(std::size_t image, const study::SeparationSetting& s) const {
    auto p = images_[image].at;
    p[0] += 1.0 * s[static_cast<std::size_t>(study::TactileParameter::gain)];
    p[1] += pitch_per_step_ * s[static_cast<std::size_t>(study::TactileParameter::period)];
    const int pattern = s[static_cast<std::size_t>(study::TactileParameter::pattern)];
    if (pattern > 0) p[2] = 2.5 * pattern;  // sine, square, triangle: 2.5, 5, 7.5 JNDs of envelope
    return p;
  }

  std::vector<AnalyticImage> images_;
  double pitch_per_step_;
};

}  // namespace vimg::test
