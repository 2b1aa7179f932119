// The matching study file (docs/format-studies.md, "Matching study file"): load_matching_study and
// parse_matching_study of storage/study/study_file.hpp.
#include <map>

#include "storage/limits.hpp"
#include "storage/named_file.hpp"
#include "storage/load_file.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/study_names.hpp"
#include "storage/study/study_xml.hpp"

namespace vimg {
namespace {

using study_xml::StudyXml;
using tinyxml2::XMLElement;

class MatchingReader {
 public:
  MatchingReader(DiagnosticList& list, const std::filesystem::path& folder, bool allow_outside)
      : xml_(list), folder_(folder) {
    named_.allow_outside_folder = allow_outside;
  }

  std::optional<MatchingStudy> run(std::string_view text) {
    tinyxml2::XMLDocument doc;
    const XMLElement* root = xml_.root(doc, text, "matchingStudy");
    if (!root) return std::nullopt;
    xml_.check_attributes(root, {"version", "seed", "repetitions", "trainingMinutes"});
    xml_.seed(root, "seed", study_.seed);
    xml_.integer(root, "repetitions", study_.repetitions, 1, kMaxStudyRepetitions);
    xml_.number(root, "trainingMinutes", study_.training_minutes, 0.0, kMaxStudyTrainingMinutes);
    xml_.check_content(root, true);
    for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string_view name = e->Name();
      if (name == "maskingNoise") read_masking(e);
      else if (name == "set") read_set(e);
      else if (name == "instructions") read_text(e, study_.instructions, instructions_line_);
      else if (name == "consent") read_text(e, study_.consent, consent_line_);
      else xml_.error(e->GetLineNum(), "unknown element " + StudyXml::tag(e) + " in <matchingStudy>");
    }
    if (study_.sets.empty() && !sets_over_limit_) {
      xml_.error(root->GetLineNum(), "<matchingStudy> needs at least one <set> of images");
    }
    check_total(root);
    if (xml_.failed()) return std::nullopt;
    return std::move(study_);
  }

 private:
  void read_masking(const XMLElement* e) {
    if (masking_line_ != 0) {
      xml_.error(e->GetLineNum(), "second <maskingNoise> (first on line " + std::to_string(masking_line_) + ")");
      return;
    }
    masking_line_ = e->GetLineNum();
    xml_.check_attributes(e, {"device", "level"});
    xml_.check_content(e, false);
    MaskingNoise noise;
    if (const auto device = xml_.text(e, "device", true)) {
      if (device->empty()) xml_.error(e->GetLineNum(), "<maskingNoise> attribute 'device' is empty, expected an audio device's name");
      noise.audio_device = *device;
    }
    xml_.number(e, "level", noise.level, 0.0, 1.0);
    study_.masking_noise = std::move(noise);
  }

  void read_set(const XMLElement* e) {
    if (study_.sets.size() >= kMaxStudySets) {
      if (!sets_over_limit_) {
        xml_.error(e->GetLineNum(), "more than " + std::to_string(kMaxStudySets) + " sets (limit " +
                                        std::to_string(kMaxStudySets) + ")");
      }
      sets_over_limit_ = true;
      return;
    }
    xml_.check_attributes(e, {"name"});
    xml_.check_content(e, true);
    StudyImageSet set;
    xml_.name(e, "name", set.name);
    if (!set.name.empty()) {
      const auto [it, inserted] = set_lines_.emplace(set.name, e->GetLineNum());
      if (!inserted) {
        xml_.error(e->GetLineNum(), "second set named '" + StudyXml::q(set.name) + "' (first on line " +
                                        std::to_string(it->second) + ")");
      }
    }
    std::map<std::string, int> stem_lines;
    std::size_t images = 0;
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
      if (std::string_view(c->Name()) != "image") {
        xml_.error(c->GetLineNum(), "unknown element " + StudyXml::tag(c) + " in <set>");
        continue;
      }
      if (++images > kMaxStudyImagesPerSet) {
        if (images == kMaxStudyImagesPerSet + 1) {
          xml_.error(c->GetLineNum(), "more than " + std::to_string(kMaxStudyImagesPerSet) + " images in one set (limit " +
                                          std::to_string(kMaxStudyImagesPerSet) + ")");
        }
        continue;
      }
      read_image(c, set, stem_lines);
    }
    if (images < 2) {
      xml_.error(e->GetLineNum(), "<set> needs at least two <image> elements (a participant chooses among them), found " +
                                      std::to_string(images));
    }
    study_.sets.push_back(std::move(set));
  }

  void read_image(const XMLElement* e, StudyImageSet& set, std::map<std::string, int>& stem_lines) {
    xml_.check_attributes(e, {"file"});
    xml_.check_content(e, false);
    const auto file = xml_.text(e, "file", true);
    if (!file) return;
    const NamedFileReadResult read = read_named_file(folder_, *file, kMaxImageFileBytes, named_, "the study's folder");
    if (!read.read.bytes) {
      xml_.error(e->GetLineNum(), "<image> attribute 'file' = \"" + StudyXml::q(*file) + "\": " + read.read.error);
      return;
    }
    const std::string stem = study_image_name(read.path);
    if (const auto problem = study_name_problem(stem)) {
      xml_.error(e->GetLineNum(), "<image> '" + StudyXml::q(*file) + "': its name '" + StudyXml::q(stem) + "' " + *problem);
      return;
    }
    const auto [it, inserted] = stem_lines.emplace(stem, e->GetLineNum());
    if (!inserted) {
      xml_.error(e->GetLineNum(), "<image> '" + StudyXml::q(*file) + "' has the name '" + StudyXml::q(stem) +
                                      "' of the image on line " + std::to_string(it->second) +
                                      " (trial files name images by their file's stem)");
      return;
    }
    set.images.push_back(read.path.lexically_normal());
  }

  // <instructions> or <consent>: text only, at most once. Each line is trimmed; lines in a row
  // join with a space and a blank line starts a new paragraph ("\n\n").
  void read_text(const XMLElement* e, std::string& into, int& first_line) {
    if (first_line != 0) {
      xml_.error(e->GetLineNum(), "second " + StudyXml::tag(e) + " (first on line " + std::to_string(first_line) + ")");
      return;
    }
    first_line = e->GetLineNum();
    xml_.check_attributes(e, {});
    std::string raw;
    for (const tinyxml2::XMLNode* n = e->FirstChild(); n; n = n->NextSibling()) {
      if (const tinyxml2::XMLText* t = n->ToText()) raw += t->Value();
      else if (n->ToElement()) xml_.error(n->GetLineNum(), StudyXml::tag(e) + " holds text only, found " + StudyXml::tag(n->ToElement()));
    }
    std::string line;
    bool blank_seen = false;
    for (std::size_t at = 0; at <= raw.size(); ++at) {
      if (at < raw.size() && raw[at] != '\n') {
        line += raw[at];
        continue;
      }
      const std::size_t first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos) {
        blank_seen = !into.empty();
      } else {
        const std::string trimmed = line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
        if (!into.empty()) into += blank_seen ? "\n\n" : " ";
        into += trimmed;
        blank_seen = false;
      }
      line.clear();
    }
    if (into.size() > kMaxStudyTextBytes) {
      xml_.error(first_line, StudyXml::tag(e) + " holds " + std::to_string(into.size()) + " bytes, more than " +
                                 std::to_string(kMaxStudyTextBytes) + " (limit " + std::to_string(kMaxStudyTextBytes) + ")");
    }
  }

  void check_total(const XMLElement* root) {
    std::size_t total = 0;
    for (const auto& set : study_.sets) total += set.images.size() * static_cast<std::size_t>(study_.repetitions);
    if (total > kMaxStudyTrials) {
      xml_.error(root->GetLineNum(), "the study has " + std::to_string(total) + " trials (images x repetitions), more than " +
                                         std::to_string(kMaxStudyTrials) + " (limit " + std::to_string(kMaxStudyTrials) + ")");
    }
  }

  StudyXml xml_;
  std::filesystem::path folder_;
  NamedFileOptions named_;
  MatchingStudy study_;
  int masking_line_ = 0;
  int instructions_line_ = 0;
  int consent_line_ = 0;
  bool sets_over_limit_ = false;
  std::map<std::string, int> set_lines_;
};

}  // namespace

StudyFileResult<MatchingStudy> parse_matching_study(std::string_view xml, const std::string& file_name,
                                                    const std::filesystem::path& folder, bool allow_outside_files) {
  StudyFileResult<MatchingStudy> result;
  DiagnosticList list(file_name);
  result.study = MatchingReader(list, folder, allow_outside_files).run(xml);
  result.diagnostics = list.take();
  return result;
}

StudyFileResult<MatchingStudy> load_matching_study(const std::filesystem::path& file, bool allow_outside_files) {
  return load_file<StudyFileResult<MatchingStudy>>(file, kMaxStudyFileBytes, [&](std::string_view text, const std::string& name) {
    return parse_matching_study(text, name, file.parent_path(), allow_outside_files);
  });
}

}  // namespace vimg
