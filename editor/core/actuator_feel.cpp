#include "editor/core/actuator_feel.hpp"

#include <algorithm>
#include <system_error>

namespace vimg::editor {

namespace {

ActuatorProfile ideal_profile() {
  ActuatorProfile p;  // ideal, 175 Hz
  p.name = "ideal";
  return p;
}

}  // namespace

ActuatorFeel::ActuatorFeel() : analysis_(std::make_unique<FeltAnalysis>(ideal_profile())) {}

std::vector<std::string> ActuatorFeel::choose(const std::filesystem::path& profile_path) {
  FeltAnalysisLoad loaded = load_felt_analysis_file(profile_path);
  if (!loaded.analysis) {
    if (loaded.errors.empty()) loaded.errors.push_back(profile_path.string() + ": error: not an actuator profile");
    return loaded.errors;
  }
  analysis_ = std::move(loaded.analysis);
  path_ = profile_path;
  ++generation_;
  return {};
}

void ActuatorFeel::choose_ideal() {
  analysis_ = std::make_unique<FeltAnalysis>(ideal_profile());
  path_.clear();
  ++generation_;
}

const std::vector<FeltMark>& ActuatorFeel::marks(const Image& image, std::uint64_t change_count) {
  const std::pair key{change_count, generation_};
  if (marks_for_ != key) {
    marks_ = felt_marks(image, *analysis_);
    marks_for_ = key;
  }
  return marks_;
}

const FeltMark* ActuatorFeel::mark_of(const std::string& id) const {
  if (id.empty()) return nullptr;
  for (const FeltMark& m : marks_) {
    if (m.id == id) return &m;
  }
  return nullptr;
}

std::vector<FeltMark> felt_marks(const Image& image, const FeltAnalysis& analysis) {
  std::vector<FeltMark> out;
  for (FeltWarning& w : felt_warnings(image, analysis)) {
    const auto bounds = element_bounds(*w.element);
    if (!bounds) continue;
    out.push_back({w.element->id, *bounds, w.check.frequency_hz, std::move(w.message)});
  }
  return out;
}

std::vector<std::filesystem::path> profile_files(const std::vector<std::filesystem::path>& folders) {
  std::vector<std::filesystem::path> out;
  for (const auto& folder : folders) {
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) continue;
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
      if (it->path().extension() == ".xml" && it->is_regular_file(ec)) out.push_back(it->path());
    }
    std::sort(out.begin(), out.end());
    break;
  }
  return out;
}

}  // namespace vimg::editor
