// The XML reader's attribute gathering and checks: known attributes by slot, numbers from the
// parameter table, ids and duplicate ids, ignored text.
#include <tinyxml2.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/parameter_table.hpp"
#include "storage/xml_reader_detail.hpp"

namespace vimg::xml_reader_detail {

namespace {

bool is_valid_id(std::string_view id) {
  if (id.empty()) return false;
  const auto alpha = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (!alpha(id.front())) return false;
  return std::all_of(id.begin() + 1, id.end(),
                     [&](char c) { return alpha(c) || digit(c) || c == '.' || c == '-'; });
}

}  // namespace

// Indexes the attributes of `e` by their place in `known` (one pass, read by attribute()).
// Unknown attributes become warnings and are returned verbatim in order.
ExtraAttributes Reader::gather(const XMLElement& e, AttributeNames known) {
  known_ = known;
  slots_.fill(nullptr);
  std::size_t unknown = 0;
  for (const XMLAttribute* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
    const std::size_t slot = slot_of(known, a->Name());
    if (slot < known.size()) {
      slots_[slot] = a;
    } else {
      ++unknown;
    }
  }
  // One error instead of a warning per attribute, so that the cap on messages never hides it.
  if (unknown > kMaxUnknownAttributesPerElement) {
    error(e.GetLineNum(), tag(e) + " has " + std::to_string(unknown) + " unknown attributes; at most " +
                              std::to_string(kMaxUnknownAttributesPerElement) +
                              " are kept, so that the file written back stays within " +
                              std::to_string(kMaxAttributesPerElement) + " attributes per element (limit " +
                              std::to_string(kMaxUnknownAttributesPerElement) + ")");
    return {};
  }
  ExtraAttributes extras;
  for (const XMLAttribute* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
    const std::string_view name = a->Name();
    if (slot_of(known, name) < known.size()) continue;
    if (list_.keeps(a->GetLineNum())) {
      warning(a->GetLineNum(), "unknown attribute '" + q(name) + "' on " + tag(e) + " kept as is");
    } else {
      list_.count(Diagnostic::Severity::warning);
    }
    extras.emplace_back(a->Name(), a->Value());
  }
  return extras;
}

// The place of `name` in `names`, or names.size(). Attribute names are short and mostly differ in
// length or first letter, which are compared first.
std::size_t Reader::slot_of(AttributeNames names, std::string_view name) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string_view k = names[i];
    if (k.size() == name.size() && !name.empty() && k[0] == name[0] && k == name) return i;
  }
  return names.size();
}

// An attribute of the element last gathered.
const XMLAttribute* Reader::attribute(const XMLElement& e, std::string_view name) const {
  const std::size_t slot = slot_of(known_, name);
  if (slot == known_.size()) return e.FindAttribute(std::string(name).c_str());
  return slots_[slot];
}

// Reads the number attribute `name` of `owner` (storage/parameter_table.hpp): its default when
// it is absent (absent and required is an error), the value as read when it is out of range.
double Reader::number(const XMLElement& e, ParameterOwner owner, std::string_view name) {
  const ParameterSpec& spec = *find_parameter(owner, name);
  const double fallback = spec.required ? 0.0 : spec.default_value;
  const XMLAttribute* a = attribute(e, name);
  if (a == nullptr) {
    if (spec.required) error(e.GetLineNum(), tag(e) + " is missing required attribute '" + std::string(name) + "'");
    return fallback;
  }
  const ParsedNumber parsed = parse_decimal(a->Value());
  if (const auto* reason = std::get_if<std::string>(&parsed)) {
    error(a->GetLineNum(), tag(e) + " attribute '" + std::string(name) + "' = \"" + q(a->Value()) + "\" " + *reason);
    return fallback;
  }
  const double value = std::get<double>(parsed);
  if (!in_range(spec, value)) {
    readable_error(a->GetLineNum(), out_of_range_message(spec, q(a->Value())));
    value_problems_.push_back({a->GetLineNum(), path_, &spec, value});
  }
  return value;
}

void Reader::read_id(const XMLElement& e, Element& element) {
  const XMLAttribute* a = attribute(e, "id");
  if (a == nullptr) return;
  element.id = a->Value();
  if (!is_valid_id(element.id)) {
    readable_error(a->GetLineNum(), tag(e) + " id \"" + q(element.id) + "\" must match [A-Za-z_][A-Za-z0-9_.-]*");
    element.id.clear();
    return;
  }
  ids_.emplace_back(std::string_view(a->Value()), a->GetLineNum());
}

// Every id used twice or more is an error at each later use, naming the first. Sorting hashes
// (with the document position) keeps this fast for 100 000 ids.
void Reader::check_duplicate_ids() {
  std::vector<std::pair<std::size_t, std::size_t>> keys;  // hash, index in ids_
  keys.reserve(ids_.size());
  for (std::size_t i = 0; i < ids_.size(); ++i) keys.emplace_back(std::hash<std::string_view>{}(ids_[i].first), i);
  std::sort(keys.begin(), keys.end());
  for (std::size_t run = 0; run < keys.size();) {
    std::size_t end = run + 1;
    while (end < keys.size() && keys[end].first == keys[run].first) ++end;
    for (std::size_t j = run + 1; j < end; ++j) {
      const auto& later = ids_[keys[j].second];
      for (std::size_t k = run; k < j; ++k) {
        const auto& first = ids_[keys[k].second];
        if (first.first != later.first) continue;  // a hash collision, not a duplicate
        readable_error(later.second, "duplicate id '" + q(later.first) + "' (first used on line " +
                                std::to_string(first.second) + ")");
        break;
      }
    }
    run = end;
  }
}

void Reader::note_text(const XMLNode& node, const XMLElement& parent) {
  if (node.ToText() != nullptr) {
    warning(node.GetLineNum(), "text inside " + tag(parent) + " is ignored");
  }
}

}  // namespace vimg::xml_reader_detail
