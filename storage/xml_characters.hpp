#pragma once
// The characters XML 1.0 allows, checked where tinyxml2 is lax: it accepts control characters,
// references to characters XML forbids (&#0;, surrogates), undefined entities (&foo;), a bare '&'
// and '<' inside an attribute value, none of which is well-formed XML. A file holding them is
// refused by name before it is parsed (storage/xml_limits.cpp calls these).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace vimg {

// The offset of the first byte XML allows nowhere (C0 controls except tab, newline and carriage
// return; NUL is reported on its own before this), or npos.
std::size_t find_forbidden_control_byte(std::string_view text);

// `text` starts with '&': what is wrong with the reference there, or nothing when it is one of
// the five predefined entities or a reference to a character XML allows.
std::optional<std::string> reference_error(std::string_view text);

}  // namespace vimg
