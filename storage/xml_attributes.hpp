#pragma once
// The one way the XML readers read an element's attributes: study files, volume scenes and actuator
// profiles (the image reader gathers its attributes by the parameter table, storage/xml_reader*,
// and words its numbers' problems with the same functions). Numbers are read in the project's one
// grammar (storage/number_text.hpp) and checked against a NumberRange; every problem goes to one
// DiagnosticList at the element's line, with input escaped:
//   "<tag> needs attribute 'name'"                      (a required attribute is missing)
//   "attribute 'name': 'text' is not a number"          (parse_decimal's reason)
//   "attribute 'name' must be in [0.5, 200], got 500"   (storage/number_range.hpp's words)
//   "attribute 'name' must be a whole number in 0..10, got 'x'"
//   "attribute 'name' must be true or false, got 'x'"
//   "unknown attribute 'name' on <tag>"
#include <tinyxml2.h>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "storage/diagnostic.hpp"
#include "storage/number_range.hpp"

namespace vimg {

class XmlAttributes {
 public:
  explicit XmlAttributes(DiagnosticList& list) : list_(list) {}

  void error(int line, std::string_view message) { list_.error(line, message); }
  bool failed() const { return list_.has_errors(); }

  // Every attribute of `e` must be one of `allowed`.
  void check_attributes(const tinyxml2::XMLElement& e, std::initializer_list<std::string_view> allowed);

  // The attribute's text, or nothing (reported when required).
  std::optional<std::string> text(const tinyxml2::XMLElement& e, const char* name, bool required = false);
  // A decimal number inside `range`, or nothing (reported when present but not valid, or required
  // and missing).
  std::optional<double> number(const tinyxml2::XMLElement& e, const char* name, const NumberRange& range,
                               bool required = false);
  // A whole number (digits only) in [min, max].
  std::optional<std::uint64_t> whole(const tinyxml2::XMLElement& e, const char* name, std::uint64_t min,
                                     std::uint64_t max, bool required = false);
  // "true" or "false" ("1" and "0" too).
  std::optional<bool> boolean(const tinyxml2::XMLElement& e, const char* name, bool required = false);

  static std::string q(std::string_view input) { return escape_input(input); }
  static std::string tag(const tinyxml2::XMLElement& e) { return "<" + q(e.Name()) + ">"; }

 private:
  DiagnosticList& list_;
};

}  // namespace vimg
