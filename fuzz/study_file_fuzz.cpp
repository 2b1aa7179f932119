// Fuzzes both study-file readers (storage/study/study_file.hpp) on the same bytes: any input gives
// located errors or a study within every rule and limit of docs/format-studies.md, never a crash; every
// message is printable and bounded. The matching reader resolves images in a folder made once
// with a.vimg, b.vimg, c.vimg, dot.vimg and sub/line.vimg (any other name is a located error).
#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <string_view>

#include "fuzz/check_messages.hpp"
#include "storage/limits.hpp"
#include "storage/study/study_file.hpp"

namespace {

// Made once, removed at exit; never destroyed before that (the handler still needs it).
const std::filesystem::path& image_folder() {
  static const std::filesystem::path* const folder = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "study_file_fuzz_XXXXXX").string();
    if (!::mkdtemp(pattern.data())) std::abort();
    const auto* dir = new std::filesystem::path(pattern);
    std::filesystem::create_directories(*dir / "sub");
    for (const char* name : {"a.vimg", "b.vimg", "c.vimg", "dot.vimg", "sub/line.vimg"}) std::ofstream(*dir / name) << "<vibroimage/>";
    return dir;
  }();
  static const bool removed_at_exit = std::atexit([] {
    std::error_code ec;
    std::filesystem::remove_all(image_folder(), ec);
  }) == 0;
  (void)removed_at_exit;
  return *folder;
}

void check_matching(const vimg::StudyFileResult<vimg::MatchingStudy>& r) {
  vimg::fuzz::check_messages(r.diagnostics);
  if (r.ok() == vimg::has_errors(r.diagnostics)) std::abort();  // a study iff no error
  if (!r.ok()) return;
  const vimg::MatchingStudy& s = *r.study;
  if (s.repetitions < 1 || s.repetitions > vimg::kMaxStudyRepetitions) std::abort();
  if (!(s.training_minutes >= 0 && s.training_minutes <= vimg::kMaxStudyTrainingMinutes)) std::abort();
  if (s.masking_noise && (s.masking_noise->audio_device.empty() || !(s.masking_noise->level >= 0 && s.masking_noise->level <= 1))) {
    std::abort();
  }
  if (s.sets.empty() || s.sets.size() > vimg::kMaxStudySets) std::abort();
  std::size_t trials = 0;
  std::set<std::string> names;
  for (const auto& set : s.sets) {
    if (set.images.size() < 2 || set.images.size() > vimg::kMaxStudyImagesPerSet) std::abort();
    if (!names.insert(set.name).second || set.name.empty() || set.name.find(',') != std::string::npos) std::abort();
    std::set<std::string> stems;
    for (const auto& image : set.images) {
      if (!stems.insert(vimg::study_image_name(image)).second) std::abort();  // trial files could not tell them apart
      if (!std::filesystem::is_regular_file(image)) std::abort();
      const auto relative = image.lexically_relative(image_folder());
      if (relative.empty() || *relative.begin() == "..") std::abort();  // an image outside the study's folder
    }
    trials += set.images.size() * static_cast<std::size_t>(s.repetitions);
  }
  if (trials > vimg::kMaxStudyTrials) std::abort();
}

void check_location(const vimg::StudyFileResult<vimg::LocationStudy>& r) {
  vimg::fuzz::check_messages(r.diagnostics);
  if (r.ok() == vimg::has_errors(r.diagnostics)) std::abort();
  if (!r.ok()) return;
  const vimg::LocationStudy& s = *r.study;
  if (s.metaphors.empty() || s.metaphors.size() > 2) std::abort();
  if (s.metaphors.size() == 2 && s.metaphors[0] == s.metaphors[1]) std::abort();
  if (s.trials_per_metaphor < 1) std::abort();
  if (s.metaphors.size() * static_cast<std::size_t>(s.trials_per_metaphor) > vimg::kMaxStudyTrials) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check_matching(vimg::parse_matching_study(text, "fuzz.xml", image_folder()));
  check_location(vimg::parse_location_study(text, "fuzz.xml"));
  return 0;
}
