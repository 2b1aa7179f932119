#pragma once
// Internal to the study-file readers (matching_study_reader.cpp, location_study_reader.cpp): the
// checks every element of a study file goes through, with the wording of the other XML readers
// (storage/volume/volume_scene_reader.cpp): the structure pass and tinyxml2's refusals in words,
// unknown elements and attributes, attributes that are missing or out of range, text where none
// belongs. Every message goes to one DiagnosticList, at the element's line.
#include <tinyxml2.h>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "storage/diagnostic.hpp"
#include "storage/xml_attributes.hpp"

namespace vimg::study_xml {

using tinyxml2::XMLElement;

class StudyXml {
 public:
  explicit StudyXml(DiagnosticList& list) : list_(list), attributes_(list) {}

  // Checks the size, the structure limits and the parse, then that the root is <root_name
  // version="1">; returns the root, or nullptr once the problem is reported.
  const XMLElement* root(tinyxml2::XMLDocument& doc, std::string_view xml, std::string_view root_name);

  void error(int line, std::string_view message) { list_.error(line, message); }
  bool failed() const { return list_.has_errors(); }

  // Every attribute of `e` must be one of `allowed` (the checks are storage/xml_attributes.hpp's).
  void check_attributes(const XMLElement* e, std::initializer_list<std::string_view> allowed);
  // Text (other than blanks) in `e` is an error; so is any child element when `children` is false.
  void check_content(const XMLElement* e, bool children);

  // The attribute's text, or nothing (reported when required).
  std::optional<std::string> text(const XMLElement* e, const char* name, bool required);
  // A decimal number in [min, max], stored in `out` when present and valid.
  void number(const XMLElement* e, const char* name, double& out, double min, double max);
  // A whole number in [min, max].
  void integer(const XMLElement* e, const char* name, int& out, int min, int max);
  // A seed: a whole number in 0..2^64-1.
  void seed(const XMLElement* e, const char* name, std::uint64_t& out);
  // A name that may become a cell of a trial file (study_name_problem), stored when valid.
  void name(const XMLElement* e, const char* attribute, std::string& out);

  static std::string q(std::string_view input) { return escape_input(input); }
  static std::string tag(const XMLElement* e) { return "<" + q(e->Name()) + ">"; }

 private:
  DiagnosticList& list_;
  XmlAttributes attributes_;  // the attribute checks every XML reader shares
};

}  // namespace vimg::study_xml
