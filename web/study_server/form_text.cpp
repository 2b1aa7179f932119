#include "web/study_server/form_text.hpp"

#include <algorithm>

#include "web/server/http_message.hpp"

namespace vimg::web {

namespace {

bool decode(std::string_view text, std::string& out) {
  out.clear();
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '+') {
      c = ' ';
    } else if (c == '%') {
      const int high = i + 1 < text.size() ? hex_digit(text[i + 1]) : -1;
      const int low = i + 2 < text.size() ? hex_digit(text[i + 2]) : -1;
      if (high < 0 || low < 0) return false;
      c = static_cast<char>(high * 16 + low);
      i += 2;
    }
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) return false;
    out += c;
  }
  return true;
}

}  // namespace

std::optional<std::string> FormFields::get(const std::string& name) const {
  const auto it = fields.find(name);
  if (it == fields.end()) return std::nullopt;
  return it->second;
}

FormFields parse_form_text(std::string_view text) {
  FormFields form;
  if (text.empty()) return form;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('&', start), text.size());
    const std::string_view field = text.substr(start, end - start);
    const std::size_t equals = field.find('=');
    std::string name, value;
    if (equals == std::string_view::npos || equals == 0) {
      form.error = "a field without a name or without '='";
    } else if (!decode(field.substr(0, equals), name) || !decode(field.substr(equals + 1), value)) {
      form.error = "a bad %-escape or a control character";
    } else if (form.fields.size() == kMaxFormFields) {
      form.error = "more than " + std::to_string(kMaxFormFields) + " fields";
    } else if (!form.fields.emplace(name, value).second) {
      form.error = "field '" + name + "' given twice";
    }
    if (!form.error.empty()) {
      form.fields.clear();
      return form;
    }
    start = end + 1;
  }
  return form;
}

std::string form_escape(std::string_view value) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : value) {
    const auto byte = static_cast<unsigned char>(c);
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '.' || c == '_' ||
        c == '~') {
      out += c;
    } else {
      out += '%';
      out += kDigits[byte >> 4];
      out += kDigits[byte & 15];
    }
  }
  return out;
}

}  // namespace vimg::web
