#include "study/separate_render_space.hpp"

#include <algorithm>
#include <atomic>

#include "storage/parallel_tasks.hpp"
#include "study/compare_render.hpp"

namespace vimg::study {

RenderSeparationSpace::RenderSeparationSpace(std::vector<Image> originals,
                                             const std::vector<DiscriminationFeatures>& features,
                                             RenderSpaceOptions options)
    : originals_(std::move(originals)), options_(std::move(options)) {
  const std::size_t n = originals_.size();
  variants_.resize(n);
  original_weak_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (options_.weak_primitives) {
      original_weak_[i] = options_.weak_primitives(originals_[i]);
      std::sort(original_weak_[i].begin(), original_weak_[i].end());
    }
    Variant& v = variant(i, SeparationSetting{});
    features_[v.features] = std::make_unique<DiscriminationFeatures>(features[i]);
    original_features_.push_back(v.features);
  }
}

RenderSeparationSpace::Variant& RenderSeparationSpace::variant(std::size_t image, const SeparationSetting& setting) {
  auto& map = variants_[image];
  const auto found = map.find(setting);
  if (found != map.end()) return found->second;
  Variant v;
  v.image = apply_setting(originals_[image], setting);
  if (options_.weak_primitives && setting != SeparationSetting{}) {
    // Allowed when every primitive that is weak now was weak in the original.
    std::vector<std::size_t> weak = options_.weak_primitives(v.image);
    std::sort(weak.begin(), weak.end());
    v.allowed = std::includes(original_weak_[image].begin(), original_weak_[image].end(), weak.begin(), weak.end());
    if (!v.allowed) ++refused_weak_;
  }
  Variant& stored = map.emplace(setting, std::move(v)).first->second;
  const std::string key = std::to_string(image) + "|" + tactile_key(stored.image);
  const auto known = by_key_.find(key);
  if (known != by_key_.end()) {
    stored.features = known->second;
  } else {
    stored.features = features_.size();
    features_.emplace_back();
    feature_image_.push_back(&stored.image);
    by_key_.emplace(key, stored.features);
  }
  return stored;
}

const Image& RenderSeparationSpace::variant_image(std::size_t image, const SeparationSetting& setting) {
  return variant(image, setting).image;
}

bool RenderSeparationSpace::allowed(std::size_t image, const SeparationSetting& setting) {
  return variant(image, setting).allowed;
}

bool RenderSeparationSpace::render_missing(const std::vector<std::size_t>& wanted) {
  std::vector<std::size_t> missing;
  for (const std::size_t f : wanted)
    if (!features_[f] && std::find(missing.begin(), missing.end(), f) == missing.end()) missing.push_back(f);
  if (missing.empty()) return true;
  std::atomic<bool> stopped{false};
  std::vector<std::unique_ptr<DiscriminationFeatures>> out(missing.size());
  run_tasks(missing.size(), options_.threads, [&](std::size_t k, int) {
    if (stopped.load()) return;
    auto samples = render_for_compare(*feature_image_[missing[k]], options_.gestures, options_.response,
                                      options_.should_stop);
    if (!samples) {
      stopped.store(true);
      return;
    }
    const std::vector<double> wide(samples->begin(), samples->end());
    out[k] = std::make_unique<DiscriminationFeatures>(analyse_discrimination(wide, options_.calibration));
  });
  if (stopped.load() || (options_.should_stop && options_.should_stop())) return false;
  for (std::size_t k = 0; k < missing.size(); ++k) features_[missing[k]] = std::move(out[k]);
  rendered_ += static_cast<int>(missing.size());
  return true;
}

const CueDistances& RenderSeparationSpace::pair(std::size_t fa, std::size_t fb) {
  const std::pair<std::size_t, std::size_t> key{std::min(fa, fb), std::max(fa, fb)};
  const auto found = pairs_.find(key);
  if (found != pairs_.end()) return found->second;
  static const CueDistances kNone{};
  if (!render_missing({fa, fb}) || !features_[fa] || !features_[fb]) return kNone;  // interrupted
  const CueDistances d = fa == fb ? CueDistances{} : cue_distances(*features_[key.first], *features_[key.second]);
  return pairs_.emplace(key, d).first->second;
}

double RenderSeparationSpace::change_jnd(std::size_t image, const SeparationSetting& setting) {
  const std::size_t f = variant(image, setting).features;
  return combined_distance_jnd(pair(original_features_[image], f), options_.constants);
}

CueDistances RenderSeparationSpace::cues(std::size_t i, const SeparationSetting& a, std::size_t j,
                                         const SeparationSetting& b) {
  const std::size_t fa = variant(i, a).features;
  const std::size_t fb = variant(j, b).features;
  return pair(fa, fb);
}

bool RenderSeparationSpace::prepare(const std::vector<SeparationCandidate>& batch,
                                    const std::vector<SeparationSetting>& state) {
  if (options_.should_stop && options_.should_stop()) return false;
  // Every feature the batch and the state need, rendered at once.
  std::vector<std::size_t> wanted;
  for (std::size_t j = 0; j < state.size(); ++j) wanted.push_back(variant(j, state[j]).features);
  for (const SeparationCandidate& c : batch) wanted.push_back(variant(c.image, c.setting).features);
  if (!render_missing(wanted)) return false;
  // Every pair the batch's scores need: the candidate against the other images' current variants
  // and against its own original.
  std::vector<std::pair<std::size_t, std::size_t>> todo;
  const auto need = [&](std::size_t fa, std::size_t fb) {
    if (fa == fb) return;
    const std::pair<std::size_t, std::size_t> key{std::min(fa, fb), std::max(fa, fb)};
    if (pairs_.count(key) == 0 && std::find(todo.begin(), todo.end(), key) == todo.end()) todo.push_back(key);
  };
  for (std::size_t i = 0; i < state.size(); ++i) {
    const std::size_t fi = variant(i, state[i]).features;
    need(fi, original_features_[i]);
    for (std::size_t j = i + 1; j < state.size(); ++j) need(fi, variant(j, state[j]).features);
  }
  for (const SeparationCandidate& c : batch) {
    const std::size_t fc = variant(c.image, c.setting).features;
    need(fc, original_features_[c.image]);
    for (std::size_t j = 0; j < state.size(); ++j)
      if (j != c.image) need(fc, variant(j, state[j]).features);
  }
  std::vector<CueDistances> out(todo.size());
  run_tasks(todo.size(), options_.threads,
            [&](std::size_t k, int) { out[k] = cue_distances(*features_[todo[k].first], *features_[todo[k].second]); });
  for (std::size_t k = 0; k < todo.size(); ++k) pairs_.emplace(todo[k], out[k]);
  return !(options_.should_stop && options_.should_stop());
}

}  // namespace vimg::study
