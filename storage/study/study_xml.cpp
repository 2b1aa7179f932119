#include "storage/study/study_xml.hpp"

#include <cstdint>

#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/study/study_names.hpp"
#include "storage/xml_limits.hpp"
#include "storage/xml_parse_problem.hpp"

namespace vimg::study_xml {

namespace {

bool blank(std::string_view text) {
  for (const char c : text) {
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return false;
  }
  return true;
}

}  // namespace

const XMLElement* StudyXml::root(tinyxml2::XMLDocument& doc, std::string_view xml, std::string_view root_name) {
  if (xml.size() > kMaxStudyFileBytes) {
    error(0, "study file is larger than " + std::to_string(kMaxStudyFileBytes / 1024) + " KiB (limit " +
                 std::to_string(kMaxStudyFileBytes) + ")");
    return nullptr;
  }
  if (const auto over = check_xml_limits(xml)) {
    error(over->line, over->message);
    return nullptr;
  }
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    error(doc.ErrorLineNum(), xml_parse_problem(doc.ErrorID()));
    return nullptr;
  }
  const XMLElement* r = doc.RootElement();
  if (!r) {
    error(1, "the root element must be <" + std::string(root_name) + ">");
    return nullptr;
  }
  if (std::string_view(r->Name()) != root_name) {
    error(r->GetLineNum(), "the root element must be <" + std::string(root_name) + ">, found " + tag(r));
    return nullptr;
  }
  const char* version = r->Attribute("version");
  if (!version) {
    error(r->GetLineNum(), tag(r) + " needs attribute 'version' (\"1\")");
  } else if (std::string_view(version) != "1") {
    error(r->GetLineNum(), tag(r) + " version '" + q(version) + "' is not supported (this program reads version 1)");
  }
  return r;
}

void StudyXml::check_attributes(const XMLElement* e, std::initializer_list<std::string_view> allowed) {
  attributes_.check_attributes(*e, allowed);
}

void StudyXml::check_content(const XMLElement* e, bool children) {
  for (const tinyxml2::XMLNode* n = e->FirstChild(); n; n = n->NextSibling()) {
    if (const tinyxml2::XMLText* t = n->ToText()) {
      if (!blank(t->Value())) error(t->GetLineNum(), "text is not allowed in " + tag(e) + ": '" + q(t->Value()) + "'");
    } else if (const XMLElement* c = n->ToElement(); c && !children) {
      error(c->GetLineNum(), tag(e) + " takes no children, found " + tag(c));
    }
  }
}

std::optional<std::string> StudyXml::text(const XMLElement* e, const char* name, bool required) {
  return attributes_.text(*e, name, required);
}

void StudyXml::number(const XMLElement* e, const char* name, double& out, double min, double max) {
  if (const auto v = attributes_.number(*e, name, NumberRange::closed(min, max))) out = *v;
}

void StudyXml::integer(const XMLElement* e, const char* name, int& out, int min, int max) {
  const auto v = attributes_.whole(*e, name, static_cast<std::uint64_t>(min), static_cast<std::uint64_t>(max));
  if (v) out = static_cast<int>(*v);
}

void StudyXml::seed(const XMLElement* e, const char* name, std::uint64_t& out) {
  if (const auto v = attributes_.whole(*e, name, 0, UINT64_MAX)) out = *v;
}

void StudyXml::name(const XMLElement* e, const char* attribute, std::string& out) {
  const auto t = text(e, attribute, true);
  if (!t) return;
  if (const auto problem = study_name_problem(*t)) {
    error(e->GetLineNum(), std::string("attribute '") + attribute + "' = '" + q(*t) + "' " + *problem);
    return;
  }
  out = *t;
}

}  // namespace vimg::study_xml
