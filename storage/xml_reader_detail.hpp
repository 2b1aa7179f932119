// Internal to the XML reader (storage/xml_reader*.cpp): the Reader class that parse_image_xml runs.
#pragma once
#include <tinyxml2.h>

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "primitives/image.hpp"
#include "storage/diagnostic.hpp"
#include "storage/image_io.hpp"
#include "storage/parameter_table.hpp"

namespace vimg::xml_reader_detail {

using tinyxml2::XMLAttribute;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

// An element and its children as compact XML, for elements kept verbatim (xml_reader_elements.cpp).
std::string print_verbatim(const XMLElement& element);

// Axis-aligned bounds of a primitive, for the "wholly outside the canvas" warning.
struct Bounds {
  double min_x, min_y, max_x, max_y;
};

// The attributes each element knows, in the order of its slots.
using AttributeNames = std::span<const std::string_view>;
constexpr std::size_t kMaxSlots = 16;

// One reading of one document. The member functions are defined by what they read:
// xml_reader.cpp (run: the document checks), xml_reader_attributes.cpp (attributes, numbers, ids),
// xml_reader_root.cpp (<vibroimage>, <meta>, <interaction>), xml_reader_elements.cpp (primitives,
// groups, unknown elements).
class Reader {
 public:
  explicit Reader(const std::string& file_name) : list_(file_name, DiagnosticList::Order::by_line) {}

  LoadResult run(std::string_view xml);

 private:
  // An error that leaves the element unreadable (it is not in LoadResult::readable).
  void error(int line, std::string_view message) {
    ++hard_errors_;
    list_.error(line, message);
  }
  // An error that leaves the element readable: a value out of range, an id.
  void readable_error(int line, std::string_view message) { list_.error(line, message); }
  void warning(int line, std::string_view message) { list_.warning(line, message); }
  bool failed() const { return list_.has_errors(); }

  // Input in a message: escaped and cut (docs/limits.md, "Messages").
  static std::string q(std::string_view input) { return escape_input(input); }
  static std::string tag(const XMLElement& e) { return "<" + q(e.Name()) + ">"; }

  // xml_reader_attributes.cpp
  ExtraAttributes gather(const XMLElement& e, AttributeNames known);
  static std::size_t slot_of(AttributeNames names, std::string_view name);
  const XMLAttribute* attribute(const XMLElement& e, std::string_view name) const;
  double number(const XMLElement& e, ParameterOwner owner, std::string_view name);
  void read_id(const XMLElement& e, Element& element);
  void check_duplicate_ids();
  void note_text(const XMLNode& node, const XMLElement& parent);

  // xml_reader_root.cpp
  void read_root(const XMLElement& root, Image& image);
  void read_version(const XMLElement& root, Image& image);
  static std::string text_of(const XMLElement& e);
  void read_meta_text(const XMLElement& e, std::optional<std::string>& field);
  void collect_ignored_attributes(const XMLElement& e);
  static bool is_iso8601(std::string_view s);
  Meta read_meta(const XMLElement& e);
  InteractionParams read_interaction(const XMLElement& e);

  // xml_reader_elements.cpp
  std::optional<Element> read_element(const XMLElement& e, int depth, std::size_t index);
  std::optional<Element> read_element_body(const XMLElement& e, int depth);
  void read_primitive_children(const XMLElement& e, Element& element);
  void warn_if_outside(const XMLElement& e, const Bounds& b);
  Dot read_dot(const XMLElement& e);
  Line read_line(const XMLElement& e);
  std::vector<Point2Mm> read_points(const XMLElement& e);
  static AttributeNames surface_attributes(const XMLElement& e);
  Surface read_surface(const XMLElement& e);
  SurfacePattern read_pattern(const XMLElement& e);
  Group read_group(const XMLElement& e, int depth);

  DiagnosticList list_;
  std::size_t hard_errors_ = 0;  // errors that leave an element (or the root) unreadable
  bool root_readable_ = false;   // version and canvas size read
  std::vector<std::size_t> path_;  // of the element being read (ValueProblem::path)
  std::vector<ValueProblem> value_problems_;
  std::vector<std::pair<std::string_view, int>> ids_;  // id text (owned by the document), line
  AttributeNames known_;
  std::array<const XMLAttribute*, kMaxSlots> slots_{};
  double canvas_w_ = 0.0;
  double canvas_h_ = 0.0;
};

}  // namespace vimg::xml_reader_detail
