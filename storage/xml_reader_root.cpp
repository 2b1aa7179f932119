// The XML reader's document level: <vibroimage> (version, canvas, children), <meta> and <interaction>.
#include <tinyxml2.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "storage/image_io.hpp"
#include "storage/parameter_table.hpp"
#include "storage/xml_reader_detail.hpp"

namespace vimg::xml_reader_detail {

namespace {

constexpr std::string_view kRootAttributes[] = {"version", "width", "height"};
constexpr std::string_view kInteractionAttributes[] = {"mass", "fullSpeed", "maxDeformation"};
constexpr std::string_view kToolAttributes[] = {"name", "version"};

}  // namespace

void Reader::read_root(const XMLElement& root, Image& image) {
  image.extra_attributes = gather(root, kRootAttributes);
  read_version(root, image);
  image.width_mm = number(root, ParameterOwner::canvas, "width");
  image.height_mm = number(root, ParameterOwner::canvas, "height");
  root_readable_ = hard_errors_ == 0;
  canvas_w_ = image.width_mm;
  canvas_h_ = image.height_mm;
  int meta_line = 0;
  int interaction_line = 0;
  for (const XMLNode* node = root.FirstChild(); node != nullptr; node = node->NextSibling()) {
    const XMLElement* child = node->ToElement();
    if (child == nullptr) {
      note_text(*node, root);
      continue;
    }
    const std::string_view name = child->Name();
    if (name == "meta") {
      if (meta_line != 0) {
        error(child->GetLineNum(), "second <meta> (the first is on line " + std::to_string(meta_line) + ")");
        continue;
      }
      meta_line = child->GetLineNum();
      image.meta = read_meta(*child);
    } else if (name == "interaction") {
      if (interaction_line != 0) {
        error(child->GetLineNum(),
              "second <interaction> (the first is on line " + std::to_string(interaction_line) + ")");
        continue;
      }
      interaction_line = child->GetLineNum();
      image.interaction = read_interaction(*child);
    } else if (auto element = read_element(*child, 0, image.children.size())) {
      image.children.push_back(std::move(*element));
    }
  }
}

void Reader::read_version(const XMLElement& root, Image& image) {
  const XMLAttribute* a = attribute(root, "version");
  if (a == nullptr) {
    error(root.GetLineNum(), "<vibroimage> is missing required attribute 'version'");
    return;
  }
  const std::string_view text = a->Value();
  const auto dot = text.find('.');
  const auto digits = [](std::string_view s) {
    return !s.empty() && s.size() <= 6 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (dot == std::string_view::npos || !digits(text.substr(0, dot)) || !digits(text.substr(dot + 1))) {
    error(a->GetLineNum(), "<vibroimage> attribute 'version' = \"" + q(text) + "\" is not MAJOR.MINOR");
    return;
  }
  image.version_major = std::stoi(std::string(text.substr(0, dot)));
  image.version_minor = std::stoi(std::string(text.substr(dot + 1)));
  if (image.version_major != kFormatMajor) {
    error(a->GetLineNum(), "file format version " + std::string(text) + " is not supported: this reader reads version " +
                               std::to_string(kFormatMajor) + "." + std::to_string(kFormatMinor) +
                               (image.version_major > kFormatMajor ? " (the file is newer)" : ""));
  }
}

std::string Reader::text_of(const XMLElement& e) {
  std::string text;
  for (const XMLNode* n = e.FirstChild(); n != nullptr; n = n->NextSibling()) {
    if (const auto* t = n->ToText()) text += t->Value();
  }
  return text;
}

void Reader::read_meta_text(const XMLElement& e, std::optional<std::string>& field) {
  if (field) {
    error(e.GetLineNum(), "second " + tag(e) + " in <meta>");
    return;
  }
  collect_ignored_attributes(e);
  for (const XMLElement* c = e.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    warning(c->GetLineNum(), "element " + tag(*c) + " inside " + tag(e) + " is ignored");
  }
  field = text_of(e);
}

void Reader::collect_ignored_attributes(const XMLElement& e) {
  for (const XMLAttribute* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
    warning(a->GetLineNum(), "unknown attribute '" + q(a->Name()) + "' on " + tag(e) + " is ignored");
  }
}

bool Reader::is_iso8601(std::string_view s) {
  // YYYY-MM-DD, optionally followed by THH:MM[:SS[.fraction]][Z|+HH:MM|-HH:MM].
  size_t i = 0;
  const auto digits = [&](size_t n) {
    for (size_t k = 0; k < n; ++k, ++i) {
      if (i >= s.size() || s[i] < '0' || s[i] > '9') return false;
    }
    return true;
  };
  const auto lit = [&](char c) {
    if (i < s.size() && s[i] == c) {
      ++i;
      return true;
    }
    return false;
  };
  if (!(digits(4) && lit('-') && digits(2) && lit('-') && digits(2))) return false;
  if (i == s.size()) return true;
  if (!(lit('T') && digits(2) && lit(':') && digits(2))) return false;
  if (lit(':')) {
    if (!digits(2)) return false;
    if (lit('.')) {
      if (!digits(1)) return false;
      while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    }
  }
  if (i == s.size() || lit('Z')) return i == s.size();
  if (lit('+') || lit('-')) return digits(2) && lit(':') && digits(2) && i == s.size();
  return false;
}

Meta Reader::read_meta(const XMLElement& e) {
  Meta meta;
  meta.extra_attributes = gather(e, {});
  for (const XMLNode* node = e.FirstChild(); node != nullptr; node = node->NextSibling()) {
    const XMLElement* c = node->ToElement();
    if (c == nullptr) {
      note_text(*node, e);
      continue;
    }
    const std::string_view name = c->Name();
    if (name == "title") {
      read_meta_text(*c, meta.title);
    } else if (name == "author") {
      read_meta_text(*c, meta.author);
    } else if (name == "description") {
      read_meta_text(*c, meta.description);
    } else if (name == "created") {
      read_meta_text(*c, meta.created);
      if (meta.created && !is_iso8601(*meta.created)) {
        error(c->GetLineNum(), "<created> \"" + q(*meta.created) + "\" is not an ISO 8601 date (YYYY-MM-DD[THH:MM[:SS]][Z])");
      }
    } else if (name == "tag") {
      std::optional<std::string> tag_text;
      read_meta_text(*c, tag_text);
      meta.tags.push_back(tag_text.value_or(""));
    } else if (name == "tool") {
      if (meta.tool) {
        error(c->GetLineNum(), "second <tool> in <meta>");
        continue;
      }
      ToolInfo tool;
      const char* tool_name = c->Attribute("name");
      const char* tool_version = c->Attribute("version");
      if (tool_name == nullptr) error(c->GetLineNum(), "<tool> is missing required attribute 'name'");
      if (tool_version == nullptr) error(c->GetLineNum(), "<tool> is missing required attribute 'version'");
      tool.name = tool_name ? tool_name : "";
      tool.version = tool_version ? tool_version : "";
      tool.extra_attributes = gather(*c, kToolAttributes);
      meta.tool = tool;
    } else {
      warning(c->GetLineNum(), "unknown element " + tag(*c) + " in <meta> kept as is");
      meta.unknown_children.push_back(UnknownElement{print_verbatim(*c)});
    }
  }
  return meta;
}

InteractionParams Reader::read_interaction(const XMLElement& e) {
  InteractionParams p;
  p.extra_attributes = gather(e, kInteractionAttributes);
  p.mass_kg = number(e, ParameterOwner::interaction, "mass");
  p.full_speed_mm_per_s = number(e, ParameterOwner::interaction, "fullSpeed");
  p.max_deformation_mm = number(e, ParameterOwner::interaction, "maxDeformation");
  for (const XMLNode* node = e.FirstChild(); node != nullptr; node = node->NextSibling()) {
    if (const XMLElement* c = node->ToElement()) {
      warning(c->GetLineNum(), "unknown element " + tag(*c) + " in <interaction> kept as is");
      p.unknown_children.push_back(UnknownElement{print_verbatim(*c)});
    } else {
      note_text(*node, e);
    }
  }
  return p;
}

}  // namespace vimg::xml_reader_detail
