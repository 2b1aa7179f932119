#include "study/separate.hpp"

#include <cmath>
#include <cstdio>

#include "primitives/perception/information_transfer.hpp"
#include "storage/image_io.hpp"
#include "storage/parallel_tasks.hpp"
#include "study/separate_render_space.hpp"

namespace vimg::study {

namespace {

void fail(SeparateResult& r, const std::string& file, std::string message) {
  r.diagnostics.push_back({Diagnostic::Severity::error, file, 0, std::move(message)});
}

std::string percent(double p) {
  char text[16];
  std::snprintf(text, sizeof text, "%.0f %%", 100.0 * p);
  return text;
}

std::string bits(double b) {
  char text[24];
  std::snprintf(text, sizeof text, "%.2f bits", b);
  return text;
}

std::string list_of(const TactileParameterSet& set) {
  std::string out;
  for (std::size_t p = 0; p < kTactileParameterCount; ++p)
    if (set[p]) out += (out.empty() ? "" : ", ") + std::string(tactile_parameter_name(static_cast<TactileParameter>(p)));
  return out.empty() ? "none" : out;
}

// What limits a search that did not reach the target: the dimensions it had, the actuator's band,
// the number of images (docs/separate.md, "When the target is out of reach").
std::vector<std::string> limits_of(const SeparateRequest& q, const SeparateResult& r, int refused_weak) {
  std::vector<std::string> out;
  TactileParameterSet usable{};
  std::size_t kept = 0;
  for (std::size_t i = 0; i < r.images.size(); ++i) {
    if (r.images[i].kept) {
      ++kept;
      continue;
    }
    const TactileParameterSet present = parameters_present(r.images[i].original);
    for (std::size_t p = 0; p < kTactileParameterCount; ++p) usable[p] = usable[p] || (present[p] && q.vary[p]);
  }
  std::size_t dimensions = 0;
  for (const bool b : usable) dimensions += b ? 1 : 0;
  std::string d = "dimensions allowed: " + list_of(usable);
  if (dimensions <= 1)
    d += " (identification along one dimension saturates near 1-2 bits however far apart the images are; allow more "
         "with --vary)";
  out.push_back(d);
  if (!q.felt_band.empty())
    out.push_back("the actuator's felt band: " + q.felt_band + " (" + std::to_string(refused_weak) +
                  " candidate changes refused because a primitive would be barely felt)");
  const double n = static_cast<double>(r.images.size());
  out.push_back("the number of images: " + std::to_string(r.images.size()) + " (identifying every one at " +
                percent(r.target) + " needs about " + bits(std::log2(n) * r.target) + "; the best set found transfers " +
                bits(r.information_after_bits) + ")");
  if (kept > 0) out.push_back(std::to_string(kept) + " of the images kept as they are (--keep)");
  return out;
}

}  // namespace

double SeparateResult::total_change_jnd() const {
  double sum = 0.0;
  for (const SeparateImage& i : images) sum += i.change_jnd;
  return sum;
}

SeparateResult run_separate(const SeparateRequest& q) {
  SeparateResult r;
  r.target = q.target;
  r.vary = q.vary;
  if (!(q.target > 0.0 && q.target < 1.0)) {
    fail(r, "vimg separate", "the target must be in (0, 1)");
    return r;
  }
  for (const auto& path : q.inputs)
    if (compare_input_kind(path) != CompareInputKind::image)
      fail(r, path.string(), "a rendered signal cannot be changed; give the image it was rendered from");
  if (has_errors(r.diagnostics)) return r;

  // 1. The set as vimg compare predicts it.
  CompareRequest c;
  c.inputs = q.inputs;
  c.actuator = q.actuator;
  c.gestures = q.gestures;
  c.exploration = q.exploration;
  c.calibration = q.calibration;
  c.discrimination = q.discrimination;
  c.threads = q.threads;
  c.should_stop = q.should_stop;
  if (q.progress) q.progress("rendering the set as vimg compare does");
  r.before = run_compare(c);
  r.diagnostics = r.before.diagnostics;
  r.interrupted = r.before.interrupted;
  if (!r.before.ok()) return r;

  std::vector<Image> originals;
  for (std::size_t i = 0; i < q.inputs.size(); ++i) {
    LoadResult loaded = load_image_file(q.inputs[i]);
    if (!loaded.image) {  // it loaded a moment ago in run_compare: the file changed under us
      fail(r, q.inputs[i].string(), "cannot load the image again");
      return r;
    }
    SeparateImage im;
    im.path = r.before.inputs[i].path;
    im.label = r.before.inputs[i].label;
    im.original = *loaded.image;
    im.proposal = *loaded.image;
    im.kept = !q.keep.empty() && q.keep[i];
    im.identified_before = im.identified_after = r.before.predicted_confusion[i][i];
    r.images.push_back(std::move(im));
    originals.push_back(std::move(*loaded.image));
  }
  r.information_before_bits = information_transfer_bits(r.before.predicted_confusion);
  r.information_after_bits = r.information_before_bits;
  r.confusion_after = r.before.predicted_confusion;
  r.cues_after = r.before.cues;

  bool distinct = true;
  for (const SeparateImage& im : r.images) distinct = distinct && im.identified_before >= q.target;
  if (distinct) {
    r.already_distinct = r.reached = true;
    return r;
  }

  // 2. The search over the tactile parameters.
  RenderSpaceOptions options;
  if (!q.gestures.empty()) {
    for (const CompareGesture& g : q.gestures) options.gestures.push_back(g.gesture);
  } else {
    options.gestures.push_back(r.before.exploration->gesture);
  }
  options.response = q.actuator.response;
  options.calibration = q.calibration;
  options.constants = q.discrimination;
  options.weak_primitives = q.weak_primitives;
  options.threads = worker_thread_count(q.threads);
  options.should_stop = q.should_stop;
  options.max_variants = kSearchVariantsPerImage * static_cast<int>(originals.size());
  RenderSeparationSpace space(originals, r.before.features, std::move(options));

  SeparationRequest search;
  search.target = q.target;
  search.vary = q.vary;
  search.keep = q.keep;
  search.constants = q.discrimination;
  for (const Image& im : originals) search.present.push_back(parameters_present(im));
  if (q.progress) {
    search.progress = [&q, &space](int phase, int moves, double shortfall, double change) {
      char text[160];
      std::snprintf(text, sizeof text, "%s, move %d: shortfall %.3f, change %.2f JNDs, %d variants rendered",
                    phase == 1 ? "searching" : "pruning", moves, shortfall, change, space.variants_rendered());
      q.progress(text);
    };
  }
  const SeparationOutcome outcome = run_separation_search(space, search);
  if (outcome.interrupted || (q.should_stop && q.should_stop())) {
    r.interrupted = true;
    return r;
  }

  // 3. The proposal, scored as vimg compare scores a set.
  const std::size_t n = r.images.size();
  std::vector<DiscriminationFeatures> features;
  for (std::size_t i = 0; i < n; ++i) {
    SeparateImage& im = r.images[i];
    im.setting = outcome.settings[i];
    im.proposal = space.variant_image(i, im.setting);
    im.changes = list_changes(im.original, im.proposal);
    im.change_jnd = outcome.change_jnd[i];
  }
  r.cues_after.assign(n, std::vector<CueDistances>(n, CueDistances{}));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      r.cues_after[i][j] = r.cues_after[j][i] = space.cues(i, r.images[i].setting, j, r.images[j].setting);
  r.confusion_after = identification_confusion(r.cues_after, q.discrimination);
  for (std::size_t i = 0; i < n; ++i) r.images[i].identified_after = r.confusion_after[i][i];
  r.information_after_bits = information_transfer_bits(r.confusion_after);
  r.reached = outcome.reached;
  r.variants_rendered = space.variants_rendered();
  r.states_scored = outcome.evaluations;
  if (!r.reached) r.limits = limits_of(q, r, space.refused_as_weak());
  return r;
}

}  // namespace vimg::study
