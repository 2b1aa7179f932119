// Opening a document with its problems and the one problem list (editor/core/document_problems.hpp).
#include "editor/core/document_problems.hpp"

#include <map>
#include <set>
#include <string_view>
#include <utility>

#include "editor/core/element_ids.hpp"
#include "storage/number_text.hpp"

namespace vimg::editor {

namespace {

ParameterOwner owner_of(const Element& e) {
  if (std::holds_alternative<Line>(e.body)) return ParameterOwner::line;
  if (std::holds_alternative<Surface>(e.body)) return ParameterOwner::surface;
  return ParameterOwner::dot;
}

bool is_primitive(const Element& e) {
  return std::holds_alternative<Dot>(e.body) || std::holds_alternative<Line>(e.body) ||
         std::holds_alternative<Surface>(e.body);
}

// Renames the later of two elements with the same id, in document order.
void rename_duplicates(std::vector<Element>& elements, std::set<std::string>& seen, std::set<std::string>& used) {
  for (Element& e : elements) {
    if (!e.id.empty() && !seen.insert(e.id).second) e.id = fresh_id(kind_name(e), used);
    if (auto* g = std::get_if<Group>(&e.body)) rename_duplicates(g->children, seen, used);
  }
}

void scan(const std::vector<Element>& elements, std::vector<ClampFix>& out) {
  for (const Element& e : elements) {
    if (const auto* g = std::get_if<Group>(&e.body)) {
      scan(g->children, out);
      continue;
    }
    if (!is_primitive(e)) continue;
    const ParameterOwner owner = owner_of(e);
    for (const ParameterSpec& spec : parameter_table()) {
      if (spec.owner != owner || spec.kind != ParameterKind::number) continue;
      const double* v = number_in(e, spec);
      if (v != nullptr && !in_range(spec, *v)) out.push_back({e.id, &spec, *v});
    }
  }
}

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

// Whether `message` is the reader's out-of-range message of any number attribute.
bool is_range_message(std::string_view message) {
  for (const ParameterSpec& spec : parameter_table()) {
    if (spec.kind == ParameterKind::number && starts_with(message, out_of_range_message(spec, ""))) return true;
  }
  return false;
}

// Problems with the same severity and message merged, in the order of their first appearance.
class Merger {
 public:
  explicit Merger(std::vector<Problem>& out) : out_(out) {}
  void add(const Diagnostic& d, bool with_line) {
    const auto key = std::make_pair(d.severity, printable_message(d.message));
    auto it = index_.find(key);
    if (it == index_.end()) {
      it = index_.emplace(key, entries_.size()).first;
      entries_.push_back({d.severity, key.second, {}});
    }
    if (with_line && d.line > 0) entries_[it->second].lines.push_back(d.line);
  }
  void flush() {
    for (const Entry& e : entries_) {
      std::string where;
      for (std::size_t i = 0; i < e.lines.size(); ++i) where += (i == 0 ? "" : ", ") + std::to_string(e.lines[i]);
      const std::string prefix = e.lines.empty() ? "" : (e.lines.size() == 1 ? "line " : "lines ") + where + ": ";
      out_.push_back({e.severity, prefix + e.message, std::nullopt});
    }
    entries_.clear();
  }

 private:
  struct Entry {
    Diagnostic::Severity severity;
    std::string message;
    std::vector<int> lines;
  };
  std::vector<Problem>& out_;
  std::map<std::pair<Diagnostic::Severity, std::string>, std::size_t> index_;
  std::vector<Entry> entries_;
};

}  // namespace

std::optional<OpenedDocument> open_document_with_problems(LoadResult result) {
  std::optional<Image> image = result.image ? std::move(result.image) : std::move(result.readable);
  if (!image) return std::nullopt;
  OpenedDocument opened{std::move(*image), std::move(result.diagnostics), std::move(result.value_problems)};
  std::set<std::string> used = collect_ids(opened.image);
  std::set<std::string> seen;
  rename_duplicates(opened.image.children, seen, used);
  assign_missing_ids(opened.image);
  return opened;
}

std::vector<ClampFix> find_out_of_range(const Image& image) {
  std::vector<ClampFix> out;
  for (const ParameterSpec& spec : parameter_table()) {
    if (spec.kind != ParameterKind::number) continue;
    if (spec.owner != ParameterOwner::canvas && spec.owner != ParameterOwner::interaction) continue;
    const double* v = number_in(image, spec);
    if (v != nullptr && !in_range(spec, *v)) out.push_back({"", &spec, *v});
  }
  scan(image.children, out);
  return out;
}

std::string describe(const ClampFix& fix) {
  const ParameterSpec& spec = *fix.parameter;
  const std::string where = fix.element_id.empty() ? std::string(spec.owner == ParameterOwner::canvas ? "canvas" : "finger")
                                                   : std::string(owner_tag(spec.owner)) + " " + fix.element_id;
  const std::string unit = spec.unit == "1" ? "" : " " + std::string(spec.unit);
  return where + ": " + std::string(spec.name) + " " + format_decimal(fix.value) + unit + " is outside " +
         interval_text(spec);
}

std::vector<Problem> problem_list(const Image& image, const std::vector<Diagnostic>& load_diagnostics,
                                  const std::vector<Diagnostic>& live) {
  std::vector<Problem> out;
  for (const ClampFix& fix : find_out_of_range(image)) out.push_back({Diagnostic::Severity::error, describe(fix), fix});
  Merger merged(out);
  for (const Diagnostic& d : load_diagnostics) {
    if (!is_range_message(d.message)) merged.add(d, true);
  }
  // A message already listed merges into its entry (adding no line).
  for (const Diagnostic& d : live) {
    if (!is_range_message(d.message)) merged.add(d, false);
  }
  merged.flush();
  return out;
}

}  // namespace vimg::editor
