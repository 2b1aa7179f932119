#pragma once
// application/x-www-form-urlencoded text (an answer's body, a query): `name=value&...`, '+' a
// space, %HH a byte. Strict, for a server that writes what it reads: a name given twice, a field
// without '=', a bad %-escape, a control character (after decoding) or more than kMaxFormFields
// fields is refused as a whole. Pure.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace vimg::web {

inline constexpr std::size_t kMaxFormFields = 32;

struct FormFields {
  std::map<std::string, std::string> fields;
  std::string error;  // empty when the text was accepted
  bool ok() const { return error.empty(); }
  // The field's value, or nullopt when it is absent.
  std::optional<std::string> get(const std::string& name) const;
};

FormFields parse_form_text(std::string_view text);

// The text a form would send for `value` (letters, digits and -._~ as they are, the rest %HH).
std::string form_escape(std::string_view value);

}  // namespace vimg::web
