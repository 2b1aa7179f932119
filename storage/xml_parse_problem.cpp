#include "storage/xml_parse_problem.hpp"

#include <tinyxml2.h>

namespace vimg {

namespace {

const char* plain_words(tinyxml2::XMLError id) {
  using enum tinyxml2::XMLError;
  switch (id) {
    case XML_ERROR_PARSING_ELEMENT: return "a tag that is not closed or not well formed";
    case XML_ERROR_PARSING_ATTRIBUTE:
      return "a malformed attribute (a name without '=' and a quoted value, or a name used twice in one element)";
    case XML_ERROR_PARSING_TEXT: return "text where none may stand (after the root element, or a tag left open)";
    case XML_ERROR_PARSING_CDATA: return "a CDATA section that never ends (no ']]>')";
    case XML_ERROR_PARSING_COMMENT: return "a comment that never ends (no '-->')";
    case XML_ERROR_PARSING_DECLARATION: return "a declaration that never ends (no '?>')";
    case XML_ERROR_PARSING_UNKNOWN: return "a '<!' construct that never ends";
    case XML_ERROR_EMPTY_DOCUMENT: return "no element at all (the file is empty or only blanks)";
    case XML_ERROR_MISMATCHED_ELEMENT: return "a closing tag that does not match the element it closes";
    case XML_ERROR_PARSING: return "markup that does not parse (a name must start with a letter or '_')";
    case XML_ELEMENT_DEPTH_EXCEEDED: return "elements nested too deep";
    default: return "the parser refused it";
  }
}

}  // namespace

std::string xml_parse_problem(int error_id) {
  const auto id = static_cast<tinyxml2::XMLError>(error_id);
  return std::string("not well-formed XML: ") + plain_words(id) + " (" + tinyxml2::XMLDocument::ErrorIDToName(id) + ")";
}

}  // namespace vimg
