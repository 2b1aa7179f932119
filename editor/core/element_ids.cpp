#include "editor/core/element_ids.hpp"

namespace vimg::editor {
namespace {

void collect(const std::vector<Element>& elements, std::set<std::string>& ids) {
  for (const Element& e : elements) {
    if (!e.id.empty()) ids.insert(e.id);
    if (const auto* g = std::get_if<Group>(&e.body)) collect(g->children, ids);
  }
}

void assign_missing(std::vector<Element>& elements, std::set<std::string>& used) {
  for (Element& e : elements) {
    if (e.id.empty() && !std::holds_alternative<UnknownElement>(e.body)) e.id = fresh_id(kind_name(e), used);
    if (auto* g = std::get_if<Group>(&e.body)) assign_missing(g->children, used);
  }
}

}  // namespace

std::set<std::string> collect_ids(const Image& image) {
  std::set<std::string> ids;
  collect(image.children, ids);
  return ids;
}

std::string kind_name(const Element& element) {
  switch (element.body.index()) {
    case 0: return "dot";
    case 1: return "line";
    case 2: return "surface";
    case 3: return "group";
    default: return "element";
  }
}

std::string fresh_id(const std::string& prefix, std::set<std::string>& used) {
  for (int n = 1;; ++n) {
    std::string candidate = prefix + std::to_string(n);
    if (used.insert(candidate).second) return candidate;
  }
}

void renew_ids(Element& element, std::set<std::string>& used) {
  if (!std::holds_alternative<UnknownElement>(element.body)) element.id = fresh_id(kind_name(element), used);
  if (auto* g = std::get_if<Group>(&element.body)) {
    for (Element& c : g->children) renew_ids(c, used);
  }
}

void assign_missing_ids(Image& image) {
  std::set<std::string> used = collect_ids(image);
  assign_missing(image.children, used);
}

}  // namespace vimg::editor
