// The location study file (docs/format-studies.md, "Location study file"): load_location_study and
// parse_location_study of storage/study/study_file.hpp.
#include <array>

#include "storage/limits.hpp"
#include "storage/load_file.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/study_xml.hpp"

namespace vimg {
namespace {

using study_xml::StudyXml;
using tinyxml2::XMLElement;

class LocationReader {
 public:
  explicit LocationReader(DiagnosticList& list) : xml_(list) {}

  std::optional<LocationStudy> run(std::string_view text) {
    tinyxml2::XMLDocument doc;
    const XMLElement* root = xml_.root(doc, text, "locationStudy");
    if (!root) return std::nullopt;
    xml_.check_attributes(root, {"version", "seed", "trialsPerMetaphor", "order"});
    xml_.seed(root, "seed", study_.seed);
    xml_.integer(root, "trialsPerMetaphor", study_.trials_per_metaphor, 1, static_cast<int>(kMaxStudyTrials));
    if (const auto order = xml_.text(root, "order", false)) {
      if (*order == "blocked") study_.order = TrialOrder::blocked;
      else if (*order == "interleaved") study_.order = TrialOrder::interleaved;
      else xml_.error(root->GetLineNum(), "attribute 'order' must be blocked or interleaved, got '" + StudyXml::q(*order) + "'");
    }
    xml_.check_content(root, true);
    std::vector<LocationMetaphor> named;
    std::array<int, 2> lines{};  // where each metaphor was named
    for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
      if (std::string_view(e->Name()) != "metaphor") {
        xml_.error(e->GetLineNum(), "unknown element " + StudyXml::tag(e) + " in <locationStudy>");
        continue;
      }
      xml_.check_attributes(e, {"name"});
      xml_.check_content(e, false);
      const auto name = xml_.text(e, "name", true);
      if (!name) continue;
      const auto metaphor = parse_location_metaphor(*name);
      if (!metaphor) {
        xml_.error(e->GetLineNum(), "<metaphor> name must be roughness or transitionCue, got '" + StudyXml::q(*name) + "'");
        continue;
      }
      int& first = lines[static_cast<std::size_t>(*metaphor)];
      if (first != 0) {
        xml_.error(e->GetLineNum(), "metaphor " + std::string(location_metaphor_name(*metaphor)) + " named twice (first on line " +
                                        std::to_string(first) + ")");
        continue;
      }
      first = e->GetLineNum();
      named.push_back(*metaphor);
    }
    if (!named.empty()) study_.metaphors = std::move(named);
    const std::size_t total = study_.metaphors.size() * static_cast<std::size_t>(study_.trials_per_metaphor);
    if (total > kMaxStudyTrials) {
      xml_.error(root->GetLineNum(), "the study has " + std::to_string(total) + " trials (metaphors x trialsPerMetaphor), more than " +
                                         std::to_string(kMaxStudyTrials) + " (limit " + std::to_string(kMaxStudyTrials) + ")");
    }
    if (xml_.failed()) return std::nullopt;
    return std::move(study_);
  }

 private:
  StudyXml xml_;
  LocationStudy study_;
};

}  // namespace

StudyFileResult<LocationStudy> parse_location_study(std::string_view xml, const std::string& file_name) {
  StudyFileResult<LocationStudy> result;
  DiagnosticList list(file_name);
  result.study = LocationReader(list).run(xml);
  result.diagnostics = list.take();
  return result;
}

StudyFileResult<LocationStudy> load_location_study(const std::filesystem::path& file) {
  return load_file<StudyFileResult<LocationStudy>>(file, kMaxStudyFileBytes, parse_location_study);
}

}  // namespace vimg
