#pragma once
// The range a number read from a file must lie in, and how every reader words it: "finite", "> 0",
// "in [0, 1]", "in (0, 1000]" (storage/parameter_table.hpp's image attributes, the study files, the
// volume scenes and the actuator profiles alike, through storage/xml_attributes.hpp).
#include <limits>
#include <string>

namespace vimg {

struct NumberRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // min itself is outside the range
  bool max_open = false;

  static NumberRange closed(double lo, double hi) { return {lo, hi, false, false}; }
  static NumberRange at_least(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, false}; }
  static NumberRange above(double lo) { return {lo, std::numeric_limits<double>::infinity(), true, false}; }
};

// Finite and inside the range.
bool in_range(const NumberRange& range, double value);
// As in the readers' messages: "finite", "> 0", ">= 1", "<= 5", "in [0, 1]", "in (0, 1000]".
std::string range_text(const NumberRange& range);
// As an interval: "any finite", "> 0", "[0, 1]", "(0, 1000]".
std::string interval_text(const NumberRange& range);

}  // namespace vimg
