#include "storage/xml_attributes.hpp"

#include <charconv>
#include <system_error>
#include <variant>

#include "storage/number_text.hpp"

namespace vimg {

void XmlAttributes::check_attributes(const tinyxml2::XMLElement& e, std::initializer_list<std::string_view> allowed) {
  for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
    bool known = false;
    for (const auto name : allowed) known = known || name == a->Name();
    if (!known) error(e.GetLineNum(), "unknown attribute '" + q(a->Name()) + "' on " + tag(e));
  }
}

std::optional<std::string> XmlAttributes::text(const tinyxml2::XMLElement& e, const char* name, bool required) {
  const char* v = e.Attribute(name);
  if (!v) {
    if (required) error(e.GetLineNum(), tag(e) + " needs attribute '" + name + "'");
    return std::nullopt;
  }
  return std::string(v);
}

std::optional<double> XmlAttributes::number(const tinyxml2::XMLElement& e, const char* name, const NumberRange& range,
                                            bool required) {
  const auto t = text(e, name, required);
  if (!t) return std::nullopt;
  const ParsedNumber parsed = parse_decimal(*t);
  if (const auto* why = std::get_if<std::string>(&parsed)) {
    error(e.GetLineNum(), std::string("attribute '") + name + "': '" + q(*t) + "' " + *why);
    return std::nullopt;
  }
  const double v = std::get<double>(parsed);
  if (!in_range(range, v)) {
    error(e.GetLineNum(), std::string("attribute '") + name + "' must be " + range_text(range) + ", got " + q(*t));
    return std::nullopt;
  }
  return v;
}

std::optional<std::uint64_t> XmlAttributes::whole(const tinyxml2::XMLElement& e, const char* name, std::uint64_t min,
                                                  std::uint64_t max, bool required) {
  const auto t = text(e, name, required);
  if (!t) return std::nullopt;
  std::uint64_t v = 0;
  bool digits = !t->empty();
  for (const char c : *t) digits = digits && c >= '0' && c <= '9';
  const auto [ptr, ec] = std::from_chars(t->data(), t->data() + t->size(), v);
  if (!digits || ec != std::errc() || ptr != t->data() + t->size() || v < min || v > max) {
    error(e.GetLineNum(), std::string("attribute '") + name + "' must be a whole number in " + std::to_string(min) +
                              ".." + std::to_string(max) + ", got '" + q(*t) + "'");
    return std::nullopt;
  }
  return v;
}

std::optional<bool> XmlAttributes::boolean(const tinyxml2::XMLElement& e, const char* name, bool required) {
  const auto t = text(e, name, required);
  if (!t) return std::nullopt;
  if (*t == "true" || *t == "1") return true;
  if (*t == "false" || *t == "0") return false;
  error(e.GetLineNum(), std::string("attribute '") + name + "' must be true or false, got '" + q(*t) + "'");
  return std::nullopt;
}

}  // namespace vimg
