#pragma once
// The SeparationSpace of `vimg separate` on real images (separate.hpp): a variant of an image is
// rendered under the comparison's gestures through the actuator and analysed by the discrimination
// model exactly as run_compare does it, once per distinct set of tactile values (tactile_key); the
// cue distances of a pair of variants are computed once. The originals' features come from
// run_compare's result, not rendered again.
//
// Threads: one caller at a time; prepare() renders the batch's new variants and computes its new
// pairs on `threads` threads (storage/parallel_tasks.hpp) and blocks until done.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "primitives/gesture.hpp"
#include "primitives/image.hpp"
#include "primitives/perception/discrimination_choice.hpp"
#include "study/compare.hpp"
#include "study/separate_search.hpp"

namespace vimg::study {

struct RenderSpaceOptions {
  std::vector<Gesture> gestures;
  ResponseParams response;
  LevelCalibration calibration;
  DiscriminationConstants constants;
  std::function<std::vector<std::size_t>(const Image&)> weak_primitives;  // null: none weak
  int threads = 1;
  bool (*should_stop)() = nullptr;
  int max_variants = 0;  // the exchange phase stops once this many variants are rendered; 0: no limit
};

class RenderSeparationSpace final : public SeparationSpace {
 public:
  // `originals[i]` with `features[i]` (run_compare's).
  RenderSeparationSpace(std::vector<Image> originals, const std::vector<DiscriminationFeatures>& features,
                        RenderSpaceOptions options);

  std::size_t image_count() const override { return originals_.size(); }
  bool allowed(std::size_t image, const SeparationSetting& setting) override;
  double change_jnd(std::size_t image, const SeparationSetting& setting) override;
  CueDistances cues(std::size_t i, const SeparationSetting& a, std::size_t j, const SeparationSetting& b) override;
  bool prepare(const std::vector<SeparationCandidate>& batch, const std::vector<SeparationSetting>& state) override;
  bool may_explore() override { return options_.max_variants <= 0 || rendered_ < options_.max_variants; }

  // The image i at `setting` (as proposed).
  const Image& variant_image(std::size_t image, const SeparationSetting& setting);
  int variants_rendered() const { return rendered_; }
  int refused_as_weak() const { return refused_weak_; }

 private:
  struct Variant {
    Image image;
    std::size_t features = 0;  // index into features_
    bool allowed = true;
  };
  Variant& variant(std::size_t image, const SeparationSetting& setting);
  // Renders and analyses the variants whose features are missing.
  bool render_missing(const std::vector<std::size_t>& feature_indices);
  const CueDistances& pair(std::size_t fa, std::size_t fb);

  std::vector<Image> originals_;
  RenderSpaceOptions options_;
  std::vector<std::vector<std::size_t>> original_weak_;
  std::vector<std::map<SeparationSetting, Variant>> variants_;  // per image
  std::map<std::string, std::size_t> by_key_;                  // tactile key -> features_ index
  std::vector<std::unique_ptr<DiscriminationFeatures>> features_;  // null: not rendered yet
  std::vector<const Image*> feature_image_;                    // the image each entry renders
  std::vector<std::size_t> original_features_;                 // per image
  std::map<std::pair<std::size_t, std::size_t>, CueDistances> pairs_;
  int rendered_ = 0;
  int refused_weak_ = 0;
};

}  // namespace vimg::study
