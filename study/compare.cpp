#include "study/compare.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <mutex>

#include "storage/file_extension.hpp"
#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/parallel_tasks.hpp"
#include "study/compare_render.hpp"
#include "study/separate_search.hpp"
#include "storage/signal_file.hpp"

namespace vimg::study {

namespace {

// One input as loaded: an image to render, or the samples of a signal.
struct Loaded {
  std::optional<Image> image;
  std::vector<float> samples;
  std::vector<Diagnostic> diagnostics;
};

Loaded load_input(const std::filesystem::path& path, CompareInputKind kind) {
  Loaded l;
  if (kind == CompareInputKind::image) {
    LoadResult r = load_image_file(path);
    l.diagnostics = std::move(r.diagnostics);
    if (r.image) {
      l.image = std::move(r.image);
    } else if (!has_errors(l.diagnostics)) {
      l.diagnostics.push_back({Diagnostic::Severity::error, path.string(), 0, "cannot load the image"});
    }
    return l;
  }
  SignalReadResult r = read_signal_file(path);
  l.diagnostics = std::move(r.diagnostics);
  if (r.samples) l.samples = std::move(*r.samples);
  return l;
}

std::string mm(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// Images of a set share one canvas: an error naming every input's size otherwise.
std::optional<Diagnostic> canvas_mismatch(const std::vector<CompareInput>& inputs, const std::vector<Loaded>& loaded) {
  const Image* first = nullptr;
  const CompareInput* first_input = nullptr;
  const CompareInput* odd = nullptr;
  std::string sizes;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (!loaded[i].image) continue;
    const Image& im = *loaded[i].image;
    sizes += (sizes.empty() ? "" : ", ") + inputs[i].label + " " + mm(im.width_mm) + " x " + mm(im.height_mm) + " mm";
    if (!first) {
      first = &im;
      first_input = &inputs[i];
    } else if (!odd && (im.width_mm != first->width_mm || im.height_mm != first->height_mm)) {
      odd = &inputs[i];
    }
  }
  if (!odd) return std::nullopt;
  return Diagnostic{Diagnostic::Severity::error, odd->path, 0,
                    "the canvas differs from " + first_input->label + "'s; the images of a set share one canvas size (" +
                        sizes + ")"};
}

void fail(CompareResult& r, std::string message) {
  r.diagnostics.push_back({Diagnostic::Severity::error, "vimg compare", 0, std::move(message)});
}

}  // namespace

CompareInputKind compare_input_kind(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".wav") return CompareInputKind::wav_signal;
  if (ext == ".csv") return CompareInputKind::csv_signal;
  return CompareInputKind::image;
}

std::string confusion_warning(const std::string& label_a, const std::string& label_b, double p) {
  char text[64];
  std::snprintf(text, sizeof text, "%.2f", p);
  return label_a + " ~ " + label_b + ": likely confused (p = " + text + ")";
}

std::vector<std::string> poorly_identified_warnings(const PerceptionMatrix& confusion, const std::vector<ConfusedPair>& pairs,
                                                    const std::vector<std::string>& labels) {
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < confusion.size() && i < labels.size(); ++i) {
    const auto in_pair = [i](const ConfusedPair& pair) { return pair.a == i || pair.b == i; };
    if (confusion[i].size() <= std::max<std::size_t>(i, 1) || confusion[i][i] >= kIdentifiedTarget || std::any_of(pairs.begin(), pairs.end(), in_pair))
      continue;
    std::size_t most = i == 0 ? 1 : 0;
    for (std::size_t j = 0; j < confusion[i].size() && j < labels.size(); ++j)
      if (j != i && confusion[i][j] > confusion[i][most]) most = j;
    if (most >= labels.size() || most >= confusion[i].size()) continue;
    char text[160];
    std::snprintf(text, sizeof text, ": identified %.0f %% of the time (below %.0f %%), most often taken for ",
                  100.0 * confusion[i][i], 100.0 * kIdentifiedTarget);
    char p[32];
    std::snprintf(p, sizeof p, " (p = %.2f)", confusion[i][most]);
    warnings.push_back(labels[i] + text + labels[most] + p);
  }
  return warnings;
}

CompareResult run_compare(const CompareRequest& request) {
  CompareResult r;
  r.actuator = request.actuator;
  r.calibration = request.calibration;
  r.choice = request.choice;
  r.discrimination = request.discrimination;
  const std::size_t n = request.inputs.size();
  if (n < 2) {
    fail(r, "give at least 2 inputs to compare");
    return r;
  }
  if (n > kMaxCompareInputs) {
    fail(r, std::to_string(n) + " inputs (limit " + std::to_string(kMaxCompareInputs) + ")");
    return r;
  }
  std::map<std::string, int> names;
  for (const auto& path : request.inputs) ++names[path.filename().string()];
  for (const auto& path : request.inputs) {
    const std::string name = path.filename().string();
    r.inputs.push_back({path.string(), names[name] > 1 || name.empty() ? path.string() : name,
                        compare_input_kind(path), 0.0});
  }
  const int threads = worker_thread_count(request.threads);
  std::vector<Loaded> loaded(n);
  run_tasks(n, threads, [&](std::size_t i, int) { loaded[i] = load_input(request.inputs[i], r.inputs[i].kind); });
  for (Loaded& l : loaded) r.diagnostics.insert(r.diagnostics.end(), l.diagnostics.begin(), l.diagnostics.end());
  if (has_errors(r.diagnostics)) return r;
  if (auto mismatch = canvas_mismatch(r.inputs, loaded)) {
    r.diagnostics.push_back(*mismatch);
    return r;
  }

  std::vector<Gesture> gestures;
  const auto first_image = std::find_if(loaded.begin(), loaded.end(), [](const Loaded& l) { return l.image.has_value(); });
  if (first_image != loaded.end()) {
    r.canvas_width_mm = first_image->image->width_mm;
    r.canvas_height_mm = first_image->image->height_mm;
  }
  if (!request.gestures.empty()) {
    for (const CompareGesture& g : request.gestures) {
      gestures.push_back(g.gesture);
      r.gesture_files.push_back(g.file);
    }
  } else if (r.canvas_width_mm) {
    r.exploration = standard_exploration(*r.canvas_width_mm, *r.canvas_height_mm, request.exploration);
    if (!r.exploration) {
      fail(r, "a canvas of " + mm(*r.canvas_width_mm) + " x " + mm(*r.canvas_height_mm) +
                  " mm is too large for the standard exploration (one pass per speed and direction would last over " +
                  mm(request.exploration.max_duration_s) + " s); give the gestures to render with --gesture");
      return r;
    }
    gestures.push_back(r.exploration->gesture);
  }

  // Render (images) and analyse (all) on every thread; a render stops at should_stop().
  std::vector<StSimFeatures> stsim_features(n);
  r.features.resize(n);
  std::atomic<bool> stopped{false};
  std::mutex progress_mutex;
  std::size_t analysed = 0;
  run_tasks(n, threads, [&](std::size_t i, int) {
    if (stopped.load()) return;
    std::vector<float> samples = std::move(loaded[i].samples);
    if (loaded[i].image) {
      auto rendered = render_for_compare(*loaded[i].image, gestures, request.actuator.response, request.should_stop);
      if (!rendered) {
        stopped.store(true);
        return;
      }
      samples = std::move(*rendered);
    }
    r.inputs[i].duration_s = static_cast<double>(samples.size()) / kCompareRateHz;
    const std::vector<double> wide(samples.begin(), samples.end());
    samples = {};
    if (request.stsim) stsim_features[i] = analyse_stsim(wide);
    r.features[i] = analyse_discrimination(wide, request.calibration);
    if (request.progress) {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      request.progress(++analysed, n);
    }
  });
  if (stopped.load() || (request.should_stop && request.should_stop())) {
    r.interrupted = true;
    return r;
  }

  // Every pair on every thread (row i: ST-SIM of i against each reference, the cues of i against
  // the later inputs); the same values as stsim_matrix() and cue_matrix().
  if (request.stsim) r.stsim.assign(n, std::vector<double>(n, 1.0));
  r.cues.assign(n, std::vector<CueDistances>(n, CueDistances{}));
  run_tasks(n, threads, [&](std::size_t i, int) {
    for (std::size_t j = 0; j < n && request.stsim; ++j) {
      if (j == i) continue;
      const auto score = stsim_common_length(stsim_features[i], stsim_features[j]);
      r.stsim[i][j] = score ? score->value : std::numeric_limits<double>::quiet_NaN();
    }
    fill_cue_matrix_row(r.features, i, r.cues);
  });
  mirror_cue_matrix(r.cues);
  r.distance_jnd.assign(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) r.distance_jnd[i][j] = combined_distance_jnd(r.cues[i][j], request.discrimination);
  }
  r.predicted_confusion = identification_confusion(r.cues, request.discrimination);
  r.likely_confused = likely_confused_pairs(r.predicted_confusion, request.choice);
  for (const ConfusedPair& pair : r.likely_confused)
    r.warnings.push_back(confusion_warning(r.inputs[pair.a].label, r.inputs[pair.b].label, pair.p));
  std::vector<std::string> labels;
  for (const CompareInput& in : r.inputs) labels.push_back(in.label);
  for (std::string& w : poorly_identified_warnings(r.predicted_confusion, r.likely_confused, labels)) r.warnings.push_back(std::move(w));
  return r;
}

}  // namespace vimg::study
