// parse_image_xml: the XML image format v1 (spec section 1) read into the document model; the
// size and structure limits, well-formedness and the single <vibroimage> root are checked here.
#include <tinyxml2.h>

#include <string>
#include <string_view>
#include <utility>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/xml_limits.hpp"
#include "storage/xml_parse_problem.hpp"
#include "storage/xml_reader_detail.hpp"

namespace vimg {

namespace xml_reader_detail {

LoadResult Reader::run(std::string_view xml) {
  LoadResult result;
  if (xml.size() > kMaxImageFileBytes) {
    error(0, "file is larger than " + std::to_string(kMaxImageFileBytes / kMiB) + " MiB (limit " +
                 std::to_string(kMaxImageFileBytes) + ")");
    result.diagnostics = list_.take();
    return result;
  }
  if (const auto over = check_xml_limits(xml)) {
    error(over->line, over->message);
    result.diagnostics = list_.take();
    return result;
  }
  tinyxml2::XMLDocument doc(true, tinyxml2::PRESERVE_WHITESPACE);
  doc.Parse(xml.data(), xml.size());
  if (doc.ErrorID() == tinyxml2::XML_ERROR_EMPTY_DOCUMENT) {
    error(0, "the file is empty, expected a <vibroimage> document");
  } else if (doc.Error()) {
    error(doc.ErrorLineNum(), xml_parse_problem(doc.ErrorID()));
  } else {
    const XMLElement* root = doc.RootElement();
    if (root == nullptr) {
      error(1, "no root element, expected <vibroimage>");
    } else if (std::string_view(root->Name()) != "vibroimage") {
      error(root->GetLineNum(), "root element is " + tag(*root) + ", expected <vibroimage>");
    } else if (const XMLElement* extra = root->NextSiblingElement()) {
      error(extra->GetLineNum(), "second root element " + tag(*extra) + " after <vibroimage>");
    } else {
      Image image;
      read_root(*root, image);
      check_duplicate_ids();
      if (!failed()) {
        result.image = std::move(image);
      } else if (root_readable_) {
        result.readable = std::move(image);
        result.value_problems = std::move(value_problems_);
      }
    }
  }
  result.diagnostics = list_.take();
  return result;
}

}  // namespace xml_reader_detail

LoadResult parse_image_xml(std::string_view xml, const std::string& file_name) {
  return xml_reader_detail::Reader(file_name).run(xml);
}

}  // namespace vimg
