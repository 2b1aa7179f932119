#pragma once
// What tinyxml2's refusal of a text means, in words (every XML reader reports it the same way):
// "not well-formed XML: a closing tag that does not match the open element
// (XML_ERROR_MISMATCHED_ELEMENT)". The checks before parsing (storage/xml_limits.hpp) name the
// problems tinyxml2 misses or misnames; these are the rest.
#include <string>

namespace vimg {

// `error_id` is a tinyxml2::XMLError other than XML_SUCCESS, as XMLDocument::ErrorID() gives it.
std::string xml_parse_problem(int error_id);

}  // namespace vimg
