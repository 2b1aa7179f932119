#include "storage/study/study_xml.hpp"

#include <charconv>
#include <system_error>

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

// Digits only: no sign, no blanks, no fraction.
template <class T>
std::optional<T> whole_number(std::string_view text) {
  if (text.empty()) return std::nullopt;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
  }
  T value{};
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return value;
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
  for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
    bool known = false;
    for (const auto name : allowed) known = known || name == a->Name();
    if (!known) error(e->GetLineNum(), "unknown attribute '" + q(a->Name()) + "' on " + tag(e));
  }
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
  const char* v = e->Attribute(name);
  if (!v) {
    if (required) error(e->GetLineNum(), tag(e) + " needs attribute '" + name + "'");
    return std::nullopt;
  }
  return std::string(v);
}

void StudyXml::number(const XMLElement* e, const char* name, double& out, double min, double max) {
  const auto t = text(e, name, false);
  if (!t) return;
  const ParsedNumber parsed = parse_decimal(*t);
  if (const auto* why = std::get_if<std::string>(&parsed)) {
    error(e->GetLineNum(), std::string("attribute '") + name + "': '" + q(*t) + "' " + *why);
    return;
  }
  const double v = std::get<double>(parsed);
  if (!(v >= min && v <= max)) {
    error(e->GetLineNum(), std::string("attribute '") + name + "' must be in " + format_decimal(min) + ".." +
                               format_decimal(max) + ", got " + q(*t));
    return;
  }
  out = v;
}

void StudyXml::integer(const XMLElement* e, const char* name, int& out, int min, int max) {
  const auto t = text(e, name, false);
  if (!t) return;
  const auto v = whole_number<int>(*t);
  if (!v || *v < min || *v > max) {
    error(e->GetLineNum(), std::string("attribute '") + name + "' must be a whole number in " + std::to_string(min) +
                               ".." + std::to_string(max) + ", got '" + q(*t) + "'");
    return;
  }
  out = *v;
}

void StudyXml::seed(const XMLElement* e, const char* name, std::uint64_t& out) {
  const auto t = text(e, name, false);
  if (!t) return;
  const auto v = whole_number<std::uint64_t>(*t);
  if (!v) {
    error(e->GetLineNum(), std::string("attribute '") + name + "' must be a whole number in 0..18446744073709551615, got '" +
                               q(*t) + "'");
    return;
  }
  out = *v;
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
