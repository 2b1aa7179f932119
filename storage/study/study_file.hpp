#pragma once
// Study files (XML, docs/format-studies.md "Matching study file" and "Location study file"): what a study
// runner needs before its first trial. Read like every XML file of the project (the structure pass
// before tinyxml2, its wording for malformed XML, the limits of storage/limits.hpp); every problem
// is `FILE:LINE: error: ...`. Unlike an image's, an unknown element or attribute is an error: a
// study must run exactly as its file says.
//
//   <matchingStudy version="1" seed="2024" repetitions="5" trainingMinutes="3">
//     <instructions>Rub the screen, then ...</instructions> <consent>Your answers are ...</consent>
//     <maskingNoise device="USB Audio" level="0.2"/>
//     <set name="complexity"> <image file="dot.vimg"/> <image file="line.vimg"/> </set>
//   </matchingStudy>
//
//   <locationStudy version="1" seed="7" trialsPerMetaphor="7" order="blocked">
//     <metaphor name="roughness"/> <metaphor name="transitionCue"/>
//   </locationStudy>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"

namespace vimg {

// One set of images a participant tells apart. `images` are resolved against the study file's folder
// and confined to it like a volume scene's data files (storage/named_file.hpp): each was, when the
// study was read, a regular file (not a symbolic link) within kMaxImageFileBytes. Images are named by
// their stem (study_image_name) in the trial file, so stems are unique within a set.
struct StudyImageSet {
  std::string name;
  std::vector<std::filesystem::path> images;
};

// A study's instructions or consent text at most (storage/limits.hpp has the other study limits).
inline constexpr std::size_t kMaxStudyTextBytes = 16384;

// White noise on an audio device that is not the actuator, to hide the actuator's sound.
struct MaskingNoise {
  std::string audio_device;
  double level = 0.2;  // linear RMS, 0..1
};

struct MatchingStudy {
  std::uint64_t seed = 1;
  int repetitions = 5;  // per image and set, >= 1
  double training_minutes = 3.0;  // >= 0; 0 skips training
  std::optional<MaskingNoise> masking_noise;
  // What the participant reads first (the study page shows both; empty: its own words).
  std::string instructions;
  std::string consent;
  std::vector<StudyImageSet> sets;  // >= 1 set, each >= 2 images, stems unique within a set
};

enum class LocationMetaphor { roughness, transition_cue };  // file names: "roughness", "transitionCue"
enum class TrialOrder { blocked, interleaved };             // file names: "blocked", "interleaved"

struct LocationStudy {
  std::uint64_t seed = 1;
  // In the order the file names them (the plan counterbalances it per participant); both when the
  // file names none. Never repeated.
  std::vector<LocationMetaphor> metaphors{LocationMetaphor::roughness, LocationMetaphor::transition_cue};
  int trials_per_metaphor = 7;  // >= 1
  TrialOrder order = TrialOrder::blocked;
  // The data set of every trial is the paper's (primitives/volume/study_set.hpp, make_study_set(seed));
  // it has no parameters to change yet, so the file has no element for them.
};

// The names used in files and messages, and back (nullopt for a name that is none of them).
std::string_view location_metaphor_name(LocationMetaphor metaphor);
std::optional<LocationMetaphor> parse_location_metaphor(std::string_view name);
std::string_view trial_order_name(TrialOrder order);

// How a trial file names an image of a set: its file's stem ("shapes/dot.vimg" -> "dot").
std::string study_image_name(const std::filesystem::path& image);

template <class T>
struct StudyFileResult {
  std::optional<T> study;  // set only when there is no error
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return study.has_value(); }
};

// Reads a matching study of at most kMaxStudyFileBytes. `allow_outside_files` lets image paths lead
// out of the study file's folder (the user's explicit request only, never what a file says).
StudyFileResult<MatchingStudy> load_matching_study(const std::filesystem::path& file, bool allow_outside_files = false);
StudyFileResult<LocationStudy> load_location_study(const std::filesystem::path& file);

// The same readers on text already in memory (tests, fuzzers). `folder` is where image paths resolve.
StudyFileResult<MatchingStudy> parse_matching_study(std::string_view xml, const std::string& file_name,
                                                    const std::filesystem::path& folder, bool allow_outside_files = false);
StudyFileResult<LocationStudy> parse_location_study(std::string_view xml, const std::string& file_name);

}  // namespace vimg
