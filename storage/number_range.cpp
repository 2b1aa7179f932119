#include "storage/number_range.hpp"

#include <cmath>

#include "storage/number_text.hpp"

namespace vimg {

bool in_range(const NumberRange& r, double value) {
  if (!std::isfinite(value)) return false;
  const bool above_min = r.min_open ? value > r.min : value >= r.min;
  const bool below_max = r.max_open ? value < r.max : value <= r.max;
  return above_min && below_max;
}

std::string range_text(const NumberRange& r) {
  const bool has_min = std::isfinite(r.min);
  const bool has_max = std::isfinite(r.max);
  if (!has_min && !has_max) return "finite";
  if (!has_max) return (r.min_open ? "> " : ">= ") + format_decimal(r.min);
  if (!has_min) return (r.max_open ? "< " : "<= ") + format_decimal(r.max);
  return "in " + interval_text(r);
}

std::string interval_text(const NumberRange& r) {
  const bool has_min = std::isfinite(r.min);
  const bool has_max = std::isfinite(r.max);
  if (!has_min && !has_max) return "any finite";
  if (!has_min || !has_max) return range_text(r);
  return (r.min_open ? "(" : "[") + format_decimal(r.min) + ", " + format_decimal(r.max) + (r.max_open ? ")" : "]");
}

}  // namespace vimg
