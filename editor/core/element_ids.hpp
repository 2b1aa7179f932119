#pragma once
// Element ids: the editor names every element it creates so that selection and undo can refer
// to it, using the spec's id syntax and keeping ids unique in the document.
#include <set>
#include <string>

#include "primitives/image.hpp"

namespace vimg::editor {

// Every id in the image, groups' children included.
std::set<std::string> collect_ids(const Image& image);

// "dot", "line", "surface", "group" or "element".
std::string kind_name(const Element& element);

// The first `<prefix><n>` (n = 1, 2, ...) not in `used`; it is added to `used`.
std::string fresh_id(const std::string& prefix, std::set<std::string>& used);

// Gives the element and its descendants new ids that are not in `used`.
void renew_ids(Element& element, std::set<std::string>& used);

// Gives an id to every known element that lacks one (unknown elements are left alone).
void assign_missing_ids(Image& image);

}  // namespace vimg::editor
