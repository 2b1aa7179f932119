#pragma once
// The actuator the editor designs for (`vimg-editor --actuator P`, the Actuator choice in the
// tools panel) and what it predicts about the document: which SURFACEs and LINEs will be weak on
// it, with the words `vimg validate --actuator` prints (hal/felt_analysis.hpp). The canvas marks
// them, the inspector shows the warning, and the scope models the drive with the same profile.
// Default: the ideal actuator (acceleration = drive, nothing is weak).
// Threads: GUI thread only.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/core/geometry.hpp"
#include "hal/felt_analysis.hpp"

namespace vimg::editor {

struct FeltMark {
  std::string id;        // the element's id (may be empty inside groups)
  RectMm bounds;         // where to draw the mark
  double frequency_hz = 0.0;
  std::string message;   // the warning, as `vimg validate --actuator` words it
};

class ActuatorFeel {
 public:
  ActuatorFeel();  // the ideal actuator

  // Loads a profile file. On errors ("FILE:LINE: error: ...") the current profile stays and the
  // errors are returned; an empty result means the profile is now in use.
  std::vector<std::string> choose(const std::filesystem::path& profile_path);
  void choose_ideal();

  const FeltAnalysis& analysis() const { return *analysis_; }
  const ActuatorProfile& profile() const { return analysis_->profile(); }
  // The profile file in use; empty for the built-in ideal actuator.
  const std::filesystem::path& path() const { return path_; }
  // Grows by one with every change of profile (marks computed before are out of date).
  std::uint64_t generation() const { return generation_; }

  // The weak primitives of `image` on the current profile, in paint order (groups walked).
  // Cached: computed again only when `change_count` or the profile changed.
  const std::vector<FeltMark>& marks(const Image& image, std::uint64_t change_count);
  // The marks as last computed by marks().
  const std::vector<FeltMark>& last_marks() const { return marks_; }
  // The mark of the element `id` among the last marks computed, if it is weak.
  const FeltMark* mark_of(const std::string& id) const;

 private:
  std::unique_ptr<FeltAnalysis> analysis_;
  std::filesystem::path path_;
  std::uint64_t generation_ = 1;
  std::optional<std::pair<std::uint64_t, std::uint64_t>> marks_for_;  // (change_count, generation)
  std::vector<FeltMark> marks_;
};

// The weak primitives of `image` on `analysis` (what ActuatorFeel::marks caches).
std::vector<FeltMark> felt_marks(const Image& image, const FeltAnalysis& analysis);

// The actuator profiles (*.xml) in the first of `folders` that exists, sorted by name.
std::vector<std::filesystem::path> profile_files(const std::vector<std::filesystem::path>& folders);

}  // namespace vimg::editor
