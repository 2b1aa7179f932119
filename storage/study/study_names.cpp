#include "storage/study/study_names.hpp"

#include "storage/limits.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/trial_log.hpp"

namespace vimg {

std::optional<std::string> study_name_problem(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name.size() > kMaxStudyNameBytes) {
    return "is longer than " + std::to_string(kMaxStudyNameBytes) + " bytes (limit " + std::to_string(kMaxStudyNameBytes) + ")";
  }
  for (const char c : name) {
    const auto b = static_cast<unsigned char>(c);
    if (c == ',') return "holds a comma (it names a cell of the trial file)";
    if (c == '"') return "holds a double quote (it names a cell of the trial file)";
    if (b < 0x20 || b == 0x7F) return "holds a control character";
  }
  return std::nullopt;
}

bool valid_participant_id(std::string_view id) {
  if (id.empty() || id.size() > 64) return false;
  for (const char c : id) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

std::string_view location_metaphor_name(LocationMetaphor metaphor) {
  return metaphor == LocationMetaphor::roughness ? "roughness" : "transitionCue";
}

std::optional<LocationMetaphor> parse_location_metaphor(std::string_view name) {
  if (name == "roughness") return LocationMetaphor::roughness;
  if (name == "transitionCue") return LocationMetaphor::transition_cue;
  return std::nullopt;
}

std::string_view trial_order_name(TrialOrder order) { return order == TrialOrder::blocked ? "blocked" : "interleaved"; }

std::string study_image_name(const std::filesystem::path& image) { return image.stem().string(); }

}  // namespace vimg
