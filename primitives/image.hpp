#pragma once
// The vibrotactile image document: what a designer draws and what a file holds (spec section 1).
// Plain data in file units (mm, Hz, ratios). Storage reads and writes it, the editor edits it,
// and the player compiles it into shaders. Everything a file can say survives in it, including
// elements and attributes this version does not know.
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace vimg {

// Attributes this version does not know, kept verbatim in their original order.
using ExtraAttributes = std::vector<std::pair<std::string, std::string>>;

struct Point2Mm {
  double x_mm = 0.0;
  double y_mm = 0.0;
  friend bool operator==(const Point2Mm&, const Point2Mm&) = default;
};

struct ToolInfo {
  std::string name;
  std::string version;
  ExtraAttributes extra_attributes;
  friend bool operator==(const ToolInfo&, const ToolInfo&) = default;
};

// A child element this version does not know, kept verbatim as XML text.
struct UnknownElement {
  std::string xml;
  friend bool operator==(const UnknownElement&, const UnknownElement&) = default;
};

struct Meta {
  std::optional<std::string> title;
  std::optional<std::string> author;
  std::optional<std::string> description;
  std::optional<std::string> created;  // ISO 8601
  std::vector<std::string> tags;
  std::optional<ToolInfo> tool;
  std::vector<UnknownElement> unknown_children;
  ExtraAttributes extra_attributes;
  friend bool operator==(const Meta&, const Meta&) = default;
};

struct InteractionParams {
  double mass_kg = 0.01;
  double full_speed_mm_per_s = 100.0;
  double max_deformation_mm = 1.0;
  ExtraAttributes extra_attributes;
  std::vector<UnknownElement> unknown_children;
  friend bool operator==(const InteractionParams&, const InteractionParams&) = default;
};

struct Dot {
  double x_mm = 0.0;
  double y_mm = 0.0;
  double radius_mm = 1.0;
  double gain = 1.0;
  friend bool operator==(const Dot&, const Dot&) = default;
};

struct Line {
  double x1_mm = 0.0;
  double y1_mm = 0.0;
  double x2_mm = 0.0;
  double y2_mm = 0.0;
  double width_mm = 1.5;       // the contact band: width/2 either side of the segment
  double frequency_hz = 175.0; // natural frequency f_N
  double damping = 0.05;       // damping ratio zeta, (0, 1)
  double gain = 1.0;
  friend bool operator==(const Line&, const Line&) = default;
};

enum class SurfaceShape { rect, ellipse, polygon };
enum class SurfacePattern { sine, square, triangle };

struct Surface {
  SurfaceShape shape = SurfaceShape::rect;
  // rect: top-left corner and size
  double x_mm = 0.0;
  double y_mm = 0.0;
  double width_mm = 0.0;
  double height_mm = 0.0;
  // ellipse: centre and radii
  double cx_mm = 0.0;
  double cy_mm = 0.0;
  double rx_mm = 0.0;
  double ry_mm = 0.0;
  // polygon: at least 3 vertices
  std::vector<Point2Mm> points;
  double period_mm = 2.0;  // spatial period lambda
  double relief_mm = 0.5;  // pattern height h
  SurfacePattern pattern = SurfacePattern::sine;
  double gain = 1.0;
  friend bool operator==(const Surface&, const Surface&) = default;
};

struct Element;

struct Group {
  std::optional<std::string> name;
  std::vector<Element> children;  // paint order
  friend bool operator==(const Group&, const Group&);
};

struct Element {
  std::string id;  // unique in the document; a writer assigns one where it is empty
  std::variant<Dot, Line, Surface, Group, UnknownElement> body;
  ExtraAttributes extra_attributes;                // unknown attributes of a known element
  std::vector<UnknownElement> unknown_children;    // unknown children of a dot, line or surface
  int source_line = 0;                             // where it was read from; 0 if created in memory
  friend bool operator==(const Element& a, const Element& b) {
    // source_line is where a value came from, not part of the value.
    return a.id == b.id && a.body == b.body && a.extra_attributes == b.extra_attributes &&
           a.unknown_children == b.unknown_children;
  }
};

inline bool operator==(const Group& a, const Group& b) {
  return a.name == b.name && a.children == b.children;
}

struct Image {
  int version_major = 1;
  int version_minor = 0;
  double width_mm = 100.0;
  double height_mm = 100.0;
  std::optional<Meta> meta;
  std::optional<InteractionParams> interaction;  // absent means the defaults
  std::vector<Element> children;                 // paint order
  ExtraAttributes extra_attributes;              // unknown attributes of <vibroimage>

  // The interaction parameters in force (the defaults when the file has none).
  InteractionParams effective_interaction() const { return interaction.value_or(InteractionParams{}); }
  friend bool operator==(const Image&, const Image&) = default;
};

}  // namespace vimg
