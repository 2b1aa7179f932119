#pragma once
// The structure limits of an XML text (docs/limits.md, "Structure"), checked in one linear pass
// before tinyxml2 parses it: tinyxml2 9 compares every new attribute with all earlier ones of its
// element (quadratic), recurses once per nesting level and allocates a node per element, so a
// hostile file must be refused before it reaches the parser. The pass follows tinyxml2's lexing of
// comments, CDATA sections, declarations and quoted values, and counts lines the same way.
#include <optional>
#include <string>
#include <string_view>

namespace vimg {

struct XmlLimitError {
  int line = 0;         // 1-based line of the element or markup at fault
  std::string message;  // e.g. "<dot> has more than 64 attributes (limit 64)"
};

// Checks kMaxAttributesPerElement, kMaxXmlAttributes, kMaxXmlNestingDepth and kMaxXmlElements;
// nothing when within. It also refuses, with a message naming it, what tinyxml2 would misreport:
// text that is not UTF-8 (UTF-16/32, NUL bytes, another declared encoding) and a <!DOCTYPE>
// (tinyxml2 ignores a DTD and leaves its entities unexpanded), and what tinyxml2 accepts although
// it is not well-formed XML (storage/xml_characters.hpp): control characters, references to
// undefined entities or forbidden characters, a bare '&', '<' in an attribute value. Other
// malformed text is left to the parser.
std::optional<XmlLimitError> check_xml_limits(std::string_view xml);

}  // namespace vimg
